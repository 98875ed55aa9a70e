//! Prints the Ackermann geometry of a BMW X5 (the Webots `BmwX5` PROTO: wheelbase 2.995 m,
//! tracks 1.628 m, tyre radius 0.374 m) over a sweep of steering angles: wheel angles, turning
//! radii, geometric differential ratios, and the wheel speed targets of Webots' cruise control
//! at 20 km/h for each drive type.
//!
//! Run with `cargo run -p ackermann --example turning`.

use ackermann::{DriveType, Geometry, Turning, Wheel};

/// Central steering angles (rad), up to the pivot at π/2.
const SWEEP: [f64; 17] = [
    -0.5,
    -0.2,
    0.0,
    0.05,
    0.1,
    0.2,
    0.3,
    0.4,
    0.5,
    0.6,
    0.8,
    1.0,
    1.2,
    1.3,
    1.4,
    1.5,
    core::f64::consts::FRAC_PI_2,
];

fn main() -> Result<(), ackermann::GeometryError> {
    let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374)?;
    println!(
        "BMW X5: wheelbase L = {} m, tracks Tf = {} m, Tr = {} m, tyre radii rf = {} m, rr = {} m",
        g.wheelbase(),
        g.track_front(),
        g.track_rear(),
        g.radius_front(),
        g.radius_rear()
    );
    println!("δ = central steering angle, positive = right (Webots convention).");
    println!();

    println!("Steering angles (rad) and signed turning radii (m, positive = centre on the right)");
    println!(
        "{:>7} {:>6} | {:>8} {:>8} | {:>9} {:>9} | {:>9} {:>9} {:>9} {:>9}",
        "δ rad", "δ deg", "δ right", "δ left", "R rear", "R front", "R FR", "R FL", "R RR", "R RL"
    );
    for delta in SWEEP {
        let a = g.wheel_angles(delta);
        let radii = match g.turning(delta) {
            Turning::Straight => "  straight (infinite radius)".to_string(),
            Turning::Circle(r) => format!(
                "{:>9.3} {:>9.3} | {:>9.3} {:>9.3} {:>9.3} {:>9.3}",
                r.rear_axle,
                r.front_virtual,
                r.wheel(Wheel::FrontRight),
                r.wheel(Wheel::FrontLeft),
                r.wheel(Wheel::RearRight),
                r.wheel(Wheel::RearLeft)
            ),
        };
        println!(
            "{delta:>7.3} {:>6.1} | {:>8.4} {:>8.4} | {radii}",
            delta.to_degrees(),
            a.right,
            a.left
        );
    }
    println!();

    let speed = 20.0 / 3.6; // m/s
    println!(
        "Differential ratios and wheel speed targets at 20 km/h (rad/s; straight: {:.3})",
        speed / 0.374
    );
    println!(
        "{:>7} | {:>6} {:>6} {:>6} | {:>15} | {:>15} | {:>31}",
        "", "", "", "", "traction", "propulsion", "4x4"
    );
    println!(
        "{:>7} | {:>6} {:>6} {:>6} | {:>7} {:>7} | {:>7} {:>7} | {:>7} {:>7} {:>7} {:>7}",
        "δ rad", "front", "rear", "centr", "FR", "FL", "RR", "RL", "FR", "FL", "RR", "RL"
    );
    for delta in SWEEP {
        let ratios = g.ackermann_ratios(delta);
        let cell = |drive, wheel| {
            g.wheel_speed_targets(speed, drive, ratios)[wheel]
                .map_or_else(|| "-".to_string(), |w: f64| format!("{w:.3}"))
        };
        println!(
            "{delta:>7.3} | {:>6.3} {:>6.3} {:>6.3} | {:>7} {:>7} | {:>7} {:>7} | {:>7} {:>7} {:>7} {:>7}",
            ratios.front,
            ratios.rear,
            ratios.central,
            cell(DriveType::Traction, Wheel::FrontRight),
            cell(DriveType::Traction, Wheel::FrontLeft),
            cell(DriveType::Propulsion, Wheel::RearRight),
            cell(DriveType::Propulsion, Wheel::RearLeft),
            cell(DriveType::FourByFour, Wheel::FrontRight),
            cell(DriveType::FourByFour, Wheel::FrontLeft),
            cell(DriveType::FourByFour, Wheel::RearRight),
            cell(DriveType::FourByFour, Wheel::RearLeft),
        );
    }
    println!();
    println!(
        "Beyond δ = atan(2L/Tf) = {:.4} rad the turning centre is inside the front track: the inner",
        (2.0 * g.wheelbase() / g.track_front()).atan()
    );
    println!(
        "wheel turns past 90° (Webots' formula flips its sign there). Once R < Tr/2 the inner"
    );
    println!("rear wheel rolls backwards; at δ = π/2 the car pivots about its rear-axle centre.");
    Ok(())
}
