//! Golden values for the BMW X5 (wheelbase 2.995 m, tracks 1.628 m, tyre radii 0.374 m),
//! computed independently by `tests/golden_values.py` (mpmath, 40 digits, literal Webots
//! formulas of spec §2.4, §2.8, §2.9).
//!
//! Worked arithmetic for δ = 0.2 rad, with k = Tf/(2L) = 1.628/5.99 = 0.271786310517529:
//! * cot 0.2 = 4.933154875586894; δR = atan(1/(4.933154875586894 − 0.271786310517529))
//!   = atan(1/4.661368565069364) = 0.211326185553853; δL = atan(1/5.204941186104423)
//!   = 0.189812230058759.
//! * R = L/tan δ = 2.995/0.202710035508672 = 14.774798852382747; Rf = L/sin δ
//!   = 2.995/0.198669330795061 = 15.075301195278671.
//! * wheel radii: L/sin δR = 14.278442828148012, L/sin δL = 15.873899163723122,
//!   R ∓ 0.814 = 13.960798852382747, 15.588798852382747.
//! * ratios: front = 14.278…/(15.873… + 14.278…) = 0.473543409397432; rear = 13.960…/(2R)
//!   = 0.472453093672110; central = Rf/(Rf + R) = 0.505033523211247.
//! * 20 km/h = 5.5̅ m/s; traction ωFR = 2·5.5̅·0.473543409397432/0.374 = 14.068431651735947 rad/s.

#![allow(clippy::unwrap_used, clippy::excessive_precision)] // test helpers; digits as computed

use ackermann::{DifferentialRatios, DriveType, Geometry, Turning, Wheel};

struct Golden {
    delta: f64,
    /// δR, δL (rad).
    angles: [f64; 2],
    /// L/tan δ, L/sin δ (m).
    radii: [f64; 2],
    /// FR, FL, RR, RL signed radii (m).
    wheels: [f64; 4],
    /// front, rear, central.
    ratios: [f64; 3],
    /// ωFR, ωFL at 20 km/h, traction (rad/s).
    traction: [f64; 2],
    /// ωRR, ωRL at 20 km/h, propulsion (rad/s).
    propulsion: [f64; 2],
    /// ωFR, ωFL, ωRR, ωRL at 20 km/h, 4x4 (rad/s).
    four_by_four: [f64; 4],
}

const GOLDEN: [Golden; 6] = [
    Golden {
        delta: 0.1,
        angles: [0.10278396969730132, 0.09736240005116822],
        radii: [29.850100047661417, 29.999974964246156],
        wheels: [
            29.19015469259804,
            30.810015526334759,
            29.036100047661417,
            30.664100047661417,
        ],
        ratios: [0.4865011980147218, 0.48636520482845463, 0.50125208628857123],
        traction: [14.453392692059471, 15.255460546205532],
        propulsion: [14.449352490447256, 15.259500747817747],
        four_by_four: [
            14.489586481685598,
            15.293662852157018,
            14.413168818183213,
            15.221288324504177,
        ],
    },
    Golden {
        delta: -0.1,
        angles: [-0.09736240005116822, -0.10278396969730132],
        radii: [-29.850100047661417, -29.999974964246156],
        wheels: [
            -30.810015526334759,
            -29.19015469259804,
            -30.664100047661417,
            -29.036100047661417,
        ],
        ratios: [0.5134988019852782, 0.51363479517154537, 0.50125208628857123],
        traction: [15.255460546205532, 14.453392692059471],
        propulsion: [15.259500747817747, 14.449352490447256],
        four_by_four: [
            15.293662852157018,
            14.489586481685598,
            15.221288324504177,
            14.413168818183213,
        ],
    },
    Golden {
        delta: 0.2,
        angles: [0.21132618555385307, 0.1898122300587591],
        radii: [14.774798852382747, 15.075301195278671],
        wheels: [
            14.278442828148012,
            15.873899163723122,
            13.960798852382747,
            15.588798852382747,
        ],
        ratios: [
            0.47354340939743198,
            0.47245309367211028,
            0.50503352321124744,
        ],
        traction: [14.068431651735947, 15.640421586529056],
        propulsion: [14.036039621868992, 15.672813616396011],
        four_by_four: [
            14.210059206265669,
            15.797874436708035,
            13.89473815940766,
            15.515034674148642,
        ],
    },
    Golden {
        delta: -0.2,
        angles: [-0.1898122300587591, -0.21132618555385307],
        radii: [-14.774798852382747, -15.075301195278671],
        wheels: [
            -15.873899163723122,
            -14.278442828148012,
            -15.588798852382747,
            -13.960798852382747,
        ],
        ratios: [
            0.52645659060256802,
            0.52754690632788972,
            0.50503352321124744,
        ],
        traction: [15.640421586529056, 14.068431651735947],
        propulsion: [15.672813616396011, 14.036039621868992],
        four_by_four: [
            15.797874436708035,
            14.210059206265669,
            15.515034674148642,
            13.89473815940766,
        ],
    },
    Golden {
        delta: 0.5,
        angles: [0.57041888732305355, 0.44399924196154896],
        radii: [5.4823107265287935, 6.2470597805857971],
        wheels: [
            5.5464538255919693,
            6.9723420573722244,
            4.6683107265287935,
            6.2963107265287935,
        ],
        ratios: [0.44305010461426926, 0.4257612309294081, 0.53259974836642495],
        traction: [13.162510535183282, 16.546342703081721],
        propulsion: [12.64887792422484, 17.059975314040163],
        four_by_four: [
            14.020699597818066,
            17.625155920091913,
            11.824177449330125,
            15.947673509289902,
        ],
    },
    Golden {
        delta: -0.5,
        angles: [-0.44399924196154896, -0.57041888732305355],
        radii: [-5.4823107265287935, -6.2470597805857971],
        wheels: [
            -6.9723420573722244,
            -5.5464538255919693,
            -6.2963107265287935,
            -4.6683107265287935,
        ],
        ratios: [0.55694989538573074, 0.5742387690705919, 0.53259974836642495],
        traction: [16.546342703081721, 13.162510535183282],
        propulsion: [17.059975314040163, 12.64887792422484],
        four_by_four: [
            17.625155920091913,
            14.020699597818066,
            15.947673509289902,
            11.824177449330125,
        ],
    },
];

/// 20 km/h (m/s).
const SPEED: f64 = 20.0 / 3.6;

fn bmw_x5() -> Geometry<f64> {
    Geometry::new(2.995, 1.628, 1.628, 0.374, 0.374).unwrap()
}

#[track_caller]
fn close(actual: f64, expected: f64, tol: f64) {
    assert!(
        (actual - expected).abs() <= tol,
        "{actual} differs from {expected} by {} (> {tol})",
        (actual - expected).abs()
    );
}

#[test]
fn wheel_angles_match_golden() {
    let g = bmw_x5();
    for case in &GOLDEN {
        let a = g.wheel_angles(case.delta);
        close(a.right, case.angles[0], 1e-15);
        close(a.left, case.angles[1], 1e-15);
    }
}

#[test]
fn inverse_recovers_the_central_angle() {
    let g = bmw_x5();
    for case in &GOLDEN {
        close(
            g.central_angle_from_right(case.angles[0]),
            case.delta,
            1e-15,
        );
        close(g.central_angle_from_left(case.angles[1]), case.delta, 1e-15);
        let angles = g.wheel_angles(case.delta);
        close(g.central_angle_from_wheel_angles(angles), case.delta, 1e-15);
    }
}

#[test]
fn turning_radii_match_golden() {
    let g = bmw_x5();
    for case in &GOLDEN {
        let Turning::Circle(r) = g.turning(case.delta) else {
            panic!("δ = {} must turn", case.delta);
        };
        close(r.rear_axle, case.radii[0], 1e-12);
        close(r.front_virtual, case.radii[1], 1e-12);
        for w in Wheel::ALL {
            close(r.wheel(w), case.wheels[w.index()], 1e-12);
        }
        close(r.curvature().unwrap(), 1.0 / case.radii[0], 1e-15);
    }
}

#[test]
fn differential_ratios_match_golden() {
    let g = bmw_x5();
    for case in &GOLDEN {
        let r = g.ackermann_ratios(case.delta);
        close(r.front, case.ratios[0], 1e-15);
        close(r.rear, case.ratios[1], 1e-15);
        close(r.central, case.ratios[2], 1e-15);
    }
}

#[test]
fn wheel_targets_at_20_kmh_match_golden() {
    let g = bmw_x5();
    for case in &GOLDEN {
        let ratios = g.ackermann_ratios(case.delta);

        let t = g.wheel_speed_targets(SPEED, DriveType::Traction, ratios);
        close(t[Wheel::FrontRight].unwrap(), case.traction[0], 1e-12);
        close(t[Wheel::FrontLeft].unwrap(), case.traction[1], 1e-12);
        assert_eq!((t[Wheel::RearRight], t[Wheel::RearLeft]), (None, None));

        let p = g.wheel_speed_targets(SPEED, DriveType::Propulsion, ratios);
        assert_eq!((p[Wheel::FrontRight], p[Wheel::FrontLeft]), (None, None));
        close(p[Wheel::RearRight].unwrap(), case.propulsion[0], 1e-12);
        close(p[Wheel::RearLeft].unwrap(), case.propulsion[1], 1e-12);

        let f = g.wheel_speed_targets(SPEED, DriveType::FourByFour, ratios);
        for w in Wheel::ALL {
            close(f[w].unwrap(), case.four_by_four[w.index()], 1e-12);
        }
    }
}

#[test]
fn straight_ahead_is_exact() {
    let g = bmw_x5();
    let a = g.wheel_angles(0.0);
    assert_eq!((a.right, a.left), (0.0, 0.0));
    assert_eq!(g.turning(0.0), Turning::Straight);
    assert_eq!(g.ackermann_ratios(0.0), DifferentialRatios::EVEN);
    // 20 km/h / 0.374 m = 5.5̅ / 0.374 = 14.854426619132501 rad/s on every driven wheel.
    for drive in DriveType::ALL {
        let t = g.wheel_speed_targets(SPEED, drive, DifferentialRatios::EVEN);
        for w in Wheel::ALL {
            match t[w] {
                Some(omega) => {
                    assert!(drive.drives(w));
                    close(omega, 14.854426619132501, 1e-12);
                }
                None => assert!(!drive.drives(w)),
            }
        }
    }
}

#[test]
fn central_ratio_is_the_front_axle_share_of_the_path_whatever_the_tyres() {
    // rf = 0.35 m, rr = 0.4 m, δ = 0.2 rad: Rf/(Rf + R) = 0.50503352321124744 (Webots'
    // q·Rf/(Rf + R) would be 0.57718…, and q/2 = 0.5714… for any δ ≠ 0, however small; fixed,
    // COMPATIBILITY.md). It is the same for equal tyres and tends to 0.5 as δ → 0.
    let unequal = Geometry::new(2.995, 1.628, 1.628, 0.35, 0.4).unwrap();
    let equal = Geometry::new(2.995, 1.628, 1.628, 0.35, 0.35).unwrap();
    for g in [unequal, equal] {
        close(g.ackermann_ratios(0.2).central, 0.50503352321124744, 1e-15);
        close(g.ackermann_ratios(-0.2).central, 0.50503352321124744, 1e-15);
        close(g.ackermann_ratios(1e-9).central, 0.5, 1e-15);
        assert_eq!(g.ackermann_ratios(0.0).central, 0.5);
    }
}

#[test]
fn matches_the_literal_webots_formula_where_it_is_sane() {
    // Webots flips the inner wheel once cot δ < k, i.e. |δ| > atan(2L/Tf) = 1.3047 rad.
    let g = bmw_x5();
    let k = 1.628 / (2.0 * 2.995);
    for i in -1300..=1300 {
        let delta = f64::from(i) * 1e-3;
        if delta == 0.0 {
            continue;
        }
        let cot = 1.0 / delta.tan();
        let webots_right = (1.0 / (cot - k)).atan();
        let webots_left = (1.0 / (cot + k)).atan();
        let a = g.wheel_angles(delta);
        close(a.right, webots_right, 4e-16);
        close(a.left, webots_left, 4e-16);

        // Webots' own ratio formulas, evaluated literally.
        let (rr, rl) = (2.995 / webots_right.sin(), 2.995 / webots_left.sin());
        let rear_r = 2.995 / delta.tan() - 0.814;
        let rear_l = 2.995 / delta.tan() + 0.814;
        let (rf, rb) = (2.995 / delta.sin(), 2.995 / delta.tan());
        let r = g.ackermann_ratios(delta);
        close(r.front, rr / (rl + rr), 1e-14);
        close(r.rear, rear_r / (rear_l + rear_r), 1e-14);
        close(r.central, rf / (rf + rb), 1e-14);
    }
}

#[test]
fn beyond_the_webots_flip_the_inner_wheel_keeps_turning() {
    let g = bmw_x5();
    // δ = 1.4 rad: cot δ = 0.172476726 < k = 0.271786311, so Webots gives the inner wheel
    // atan(1/(0.172476726 − 0.271786311)) = atan(−10.069521519) = −1.471811300; the wheel that
    // actually rolls about the centre points π further round: 1.669781353 rad.
    let delta = 1.4_f64;
    let k = 1.628 / (2.0 * 2.995);
    let webots_right = (1.0 / (1.0 / delta.tan() - k)).atan();
    close(webots_right, -1.471_811_300, 1e-9);
    let a = g.wheel_angles(delta);
    close(a.right, webots_right + core::f64::consts::PI, 1e-15);
    close(a.right, 1.669_781_353, 1e-9);
    close(g.wheel_angles(-delta).left, -a.right, 0.0);
    // At the pivot: inner π − atan(2L/Tf) = π − atan(3.679361179) = 1.836172348,
    // outer atan(3.679361179) = 1.305420305.
    let pivot = g.wheel_angles(core::f64::consts::FRAC_PI_2);
    close(
        pivot.right,
        core::f64::consts::PI - (2.0 * 2.995 / 1.628_f64).atan(),
        1e-15,
    );
    close(pivot.left, (2.0 * 2.995 / 1.628_f64).atan(), 1e-15);
    close(pivot.right, 1.836_172_348, 1e-9);
    close(pivot.left, 1.305_420_305, 1e-9);
}
