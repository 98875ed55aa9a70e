//! Where a world file's car starts: the placement a controller host (the C API, `capi`) needs
//! to build the car of a [`CarDescription`](crate::world_file::CarDescription) itself.

use vehicle_model::CarParams;

use crate::vehicle::VehiclePlacement;

/// The start placement of a car with parameters `params`: x and y of the `Car` field
/// `translation` (m; the wheels start on the ground, so its z is not used) and the heading of
/// `rotation` ([`heading_of_rotation`]).
///
/// ```
/// use vehicle_model::Model;
/// let mut params = Model::BmwX5.params::<f64>();
/// params.translation = [3.0, -1.0, 0.4];
/// params.rotation = [0.0, 0.0, 1.0, 0.5];
/// let p = sim::placement::car_placement(&params);
/// assert_eq!((p.x, p.y, p.z), (3.0, -1.0, None));
/// assert!((p.yaw - 0.5).abs() < 1e-12);
/// ```
pub fn car_placement(params: &CarParams<f64>) -> VehiclePlacement {
    let [x, y, _] = params.translation;
    VehiclePlacement {
        x,
        y,
        yaw: heading_of_rotation(params.rotation),
        z: None,
    }
}

/// The heading (rad, counter-clockwise about +z from +x) of the car's forward axis under the
/// Webots `rotation` `[x, y, z, angle]` (axis and angle in rad), projected on the ground; 0 for
/// a degenerate rotation (zero or non-finite axis, non-finite angle) or a forward axis turned
/// vertical.
pub fn heading_of_rotation(rotation: [f64; 4]) -> f64 {
    let [x, y, z, angle] = rotation;
    let n = (x * x + y * y + z * z).sqrt();
    if !(n.is_finite() && n > 0.0 && angle.is_finite()) {
        return 0.0;
    }
    let (ux, uy, uz) = (x / n, y / n, z / n);
    let (s, c) = angle.sin_cos();
    // The image of (1, 0, 0): the first column of the Rodrigues rotation matrix.
    let fx = c + ux * ux * (1.0 - c);
    let fy = uy * ux * (1.0 - c) + uz * s;
    if fx.hypot(fy) < 1e-9 {
        0.0
    } else {
        fy.atan2(fx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headings_of_webots_rotations() {
        assert_eq!(heading_of_rotation([0.0, 0.0, 1.0, 0.0]), 0.0);
        assert!((heading_of_rotation([0.0, 0.0, 1.0, 1.2]) - 1.2).abs() < 1e-12);
        // A reversed axis turns the other way.
        assert!((heading_of_rotation([0.0, 0.0, -2.0, 1.2]) + 1.2).abs() < 1e-12);
        // A pitch about y (the Tractor's 0.13 rad) keeps the heading 0.
        assert!(heading_of_rotation([0.0, 1.0, 0.0, 0.13]).abs() < 1e-12);
        // Pitching the nose straight up leaves no horizontal heading: 0.
        assert_eq!(
            heading_of_rotation([0.0, 1.0, 0.0, -core::f64::consts::FRAC_PI_2]),
            0.0
        );
        assert_eq!(heading_of_rotation([0.0, 0.0, 0.0, 1.0]), 0.0);
        assert_eq!(heading_of_rotation([0.0, 0.0, 1.0, f64::NAN]), 0.0);
        // Half a turn about z faces -x: heading ±π.
        assert!(
            (heading_of_rotation([0.0, 0.0, 1.0, core::f64::consts::PI]).abs()
                - core::f64::consts::PI)
                .abs()
                < 1e-12
        );
    }
}
