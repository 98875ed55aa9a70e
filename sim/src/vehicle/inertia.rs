//! A car's mass properties, summed and diagonalised in f64 before they reach rapier's f32.
//!
//! rapier sums mass properties and diagonalises inertia tensors in f32, through `1/(1/m)`
//! and a general eigen-solver. For a mirror-symmetric car that leaves a centre of mass a few
//! nanometres off the centre line and principal axes tilted out of the car's plane of
//! symmetry by round-off: a real asymmetry to the physics, which a yaw-unstable car (driven
//! wheels spinning, rear wheels locked) amplifies into a turn. Here the sums run in f64 in a
//! fixed left-right order, so mirror-image terms cancel exactly, and a tensor with no products
//! of inertia across the plane of symmetry (`Ixy = Iyz = 0`) is diagonalised by a rotation
//! about y alone, whose quaternion has exact zeros where rapier would need them.

use ackermann::Wheel;
use proto_geom::nalgebra::{Matrix3, Rotation3, SymmetricEigen, UnitQuaternion, Vector3};
use rapier3d::prelude::{MassProperties, Rotation, Vector};

use super::spec::{ChassisSpec, VehicleSpec, WheelSpec};

/// A rigid body's mass (kg), centre of mass and inertia tensor about that centre (kg·m²), in
/// one frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Inertia {
    /// Mass (kg).
    pub mass: f64,
    /// Centre of mass (m).
    pub com: Vector3<f64>,
    /// Inertia tensor about the centre of mass (kg·m²).
    pub tensor: Matrix3<f64>,
}

impl Inertia {
    /// A body of `mass` (kg) at `com` (m) with the Webots `inertiaMatrix`
    /// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` (kg·m²) about it.
    pub fn from_webots(mass: f64, com: [f64; 3], [xx, yy, zz, xy, xz, yz]: [f64; 6]) -> Self {
        Inertia {
            mass,
            com: Vector3::from(com),
            tensor: Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz),
        }
    }

    /// A body of `mass` (kg) at `com` (m) whose principal axes are the frame's, with the
    /// principal moments `diagonal` (kg·m²).
    pub fn principal(mass: f64, com: [f64; 3], diagonal: [f64; 3]) -> Self {
        Inertia {
            mass,
            com: Vector3::from(com),
            tensor: Matrix3::from_diagonal(&Vector3::from(diagonal)),
        }
    }

    /// This body and `others` as one: the masses and first moments add, and each tensor moves
    /// to the common centre of mass by the parallel-axis theorem. The sums run in order, this
    /// body first, so mirror-image parts listed in pairs cancel exactly.
    pub fn with(&self, others: &[Inertia]) -> Inertia {
        let parts = || core::iter::once(self).chain(others);
        let mass: f64 = parts().map(|b| b.mass).sum();
        let first = parts().fold(Vector3::zeros(), |sum, b| sum + b.com * b.mass);
        let com = first / mass;
        let tensor = parts().fold(Matrix3::zeros(), |sum, b| {
            let d = b.com - com;
            sum + b.tensor + (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * b.mass
        });
        Inertia { mass, com, tensor }
    }

    /// rapier's mass properties: the principal moments and their frame, worked out in f64. A
    /// moment that round-off leaves below 0 is 0, as rapier's own diagonalisation has it.
    pub fn mass_properties(&self) -> MassProperties {
        let (moments, frame) = principal_axes(&self.tensor);
        let moments = moments.map(|m| m.max(0.0));
        let q = frame.quaternion().coords;
        MassProperties::with_principal_inertia_frame(
            Vector::new(self.com.x as f32, self.com.y as f32, self.com.z as f32),
            self.mass as f32,
            Vector::new(moments.x as f32, moments.y as f32, moments.z as f32),
            Rotation::from_xyzw(q.x as f32, q.y as f32, q.z as f32, q.w as f32),
        )
    }
}

/// The principal moments of a symmetric tensor and the rotation whose columns are their axes.
fn principal_axes(t: &Matrix3<f64>) -> (Vector3<f64>, UnitQuaternion<f64>) {
    let (xy, yz) = (t[(0, 1)], t[(1, 2)]);
    if xy == 0.0 && yz == 0.0 {
        // y is a principal axis: the x-z block turns by θ = ½·atan2(2·Ixz, Ixx − Izz), and
        // the frame is that turn about y (a rotation by −θ maps x onto (cos θ, 0, sin θ)).
        let (xx, zz, xz) = (t[(0, 0)], t[(2, 2)], t[(0, 2)]);
        let theta = 0.5 * libm::atan2(2.0 * xz, xx - zz);
        let (s, c) = libm::sincos(theta);
        let moments = Vector3::new(
            xx * c * c + 2.0 * xz * s * c + zz * s * s,
            t[(1, 1)],
            xx * s * s - 2.0 * xz * s * c + zz * c * c,
        );
        return (
            moments,
            UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -theta),
        );
    }
    // The car's data are validated finite; a tensor that is not keeps the frame's axes, and
    // the solve is bounded all the same.
    let eigen = t
        .iter()
        .all(|v| v.is_finite())
        .then(|| SymmetricEigen::try_new(*t, f64::EPSILON, 1000))
        .flatten();
    let Some(eigen) = eigen else {
        return (t.diagonal(), UnitQuaternion::identity());
    };
    let mut axes = eigen.eigenvectors;
    let mut moments = eigen.eigenvalues;
    if axes.determinant() < 0.0 {
        axes.swap_columns(1, 2);
        moments.swap_rows(1, 2);
    }
    let rotation = Rotation3::from_matrix_unchecked(axes);
    (moments, UnitQuaternion::from_rotation_matrix(&rotation))
}

/// Mass properties of the whole car in the car frame: the body (`Physics` of the Car: mass,
/// centre of mass, inertia tensor) plus the four wheels as solid cylinders at their unloaded
/// positions (axis along y). The wheels ride with the chassis, so they add to its mass and to
/// its inertia (their spin is a separate coordinate, see the tyre solve). Summed in f64 an axle
/// at a time, so that a mirror-symmetric car's centre of mass lies exactly on its centre line
/// ([`Inertia::with`]).
pub(crate) fn mass_properties(spec: &VehicleSpec) -> MassProperties {
    let wheel = |s: &WheelSpec| {
        let transverse = s.transverse_inertia();
        let p = s.position;
        Inertia::principal(
            s.mass,
            [p.x, p.y, p.z],
            [transverse, s.spin_inertia(), transverse],
        )
    };
    let w = &spec.wheels;
    body_inertia(&spec.chassis)
        .with(&[
            wheel(&w[Wheel::FrontRight]),
            wheel(&w[Wheel::FrontLeft]),
            wheel(&w[Wheel::RearRight]),
            wheel(&w[Wheel::RearLeft]),
        ])
        .mass_properties()
}

/// The car body's mass, centre of mass and inertia tensor (car frame).
pub(crate) fn body_inertia(c: &ChassisSpec) -> Inertia {
    let com = c.center_of_mass;
    Inertia::from_webots(c.mass, [com.x, com.y, com.z], c.inertia)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use vehicle_model::Model;

    fn rebuilt(p: &MassProperties) -> Matrix3<f64> {
        let m = p.reconstruct_inertia_matrix();
        Matrix3::from_fn(|i, j| f64::from(m.col(j)[i]))
    }

    #[test]
    fn a_tensor_with_a_plane_of_symmetry_turns_about_y_only() {
        // The TeslaModel3's body with its products across the plane of symmetry removed.
        let body = Inertia::from_webots(
            1847.0,
            [1.27, 0.0, 0.0],
            [4466.54, 26_116.9, 25_854.0, 0.0, -3204.91, 0.0],
        );
        let p = body.mass_properties();
        let q = p.principal_inertia_local_frame;
        assert_eq!((q.x, q.z), (0.0, 0.0));
        let back = rebuilt(&p);
        assert_eq!((back[(0, 1)], back[(1, 2)]), (0.0, 0.0));
        // Within f32 round-off of the moments (≈ 26,000 kg·m² × 2⁻²³ ≈ 0.003 kg·m²).
        assert!((back - body.tensor).abs().max() < 0.01, "{back}");
    }

    #[test]
    fn a_tensor_that_cannot_be_diagonalised_keeps_its_axes() {
        let body = Inertia::from_webots(1.0, [0.0; 3], [1.0, 2.0, 3.0, f64::NAN, 0.5, 0.1]);
        let (moments, frame) = principal_axes(&body.tensor);
        assert_eq!(moments, Vector3::new(1.0, 2.0, 3.0));
        assert_eq!(frame, UnitQuaternion::identity());
    }

    #[test]
    fn a_general_tensor_keeps_its_products() {
        let body = Inertia::from_webots(1000.0, [0.0; 3], [300.0, 400.0, 500.0, 20.0, -30.0, 10.0]);
        let back = rebuilt(&body.mass_properties());
        assert!((back - body.tensor).abs().max() < 0.01, "{back}");
    }

    #[test]
    fn mirror_image_parts_leave_the_centre_on_the_plane_of_symmetry() {
        let body = Inertia::from_webots(
            1847.0,
            [1.27, 0.0, 0.1],
            [4466.54, 26_116.9, 25_854.0, 0.0, -3204.91, 0.0],
        );
        let wheel = |x: f64, y: f64| Inertia::principal(10.4, [x, y, 0.36], [0.4, 0.67, 0.4]);
        let car = body.with(&[
            wheel(2.94, 0.86),
            wheel(2.94, -0.86),
            wheel(0.0, 0.86),
            wheel(0.0, -0.86),
        ]);
        assert_eq!(car.com.y, 0.0);
        assert_eq!((car.tensor[(0, 1)], car.tensor[(1, 2)]), (0.0, 0.0));
        assert!((car.mass - (1847.0 + 4.0 * 10.4)).abs() < 1e-9);
        // Parallel axes: each wheel adds m·(x² + z²) about y, measured from the common centre.
        let com = car.com;
        let expected_yy = 26_116.9
            + 1847.0 * ((1.27 - com.x).powi(2) + (0.1 - com.z).powi(2))
            + [2.94, 2.94, 0.0, 0.0]
                .iter()
                .map(|x| 0.67 + 10.4 * ((x - com.x).powi(2) + (0.36 - com.z).powi(2)))
                .sum::<f64>();
        assert!((car.tensor[(1, 1)] - expected_yy).abs() < 1e-9);
    }

    #[test]
    fn wheels_add_their_mass_and_move_the_centre_of_mass() {
        let spec = VehicleSpec::from_car(&Model::BmwX5.params()).unwrap_or_else(|e| panic!("{e}"));
        let mp = mass_properties(&spec);
        // 2000 kg body + 4 × 30 kg wheels.
        assert!((mp.mass() - 2120.0).abs() < 1e-3);
        // x: (2000·x_body + 60·L + 60·0)/2120.
        let x = (2000.0 * spec.chassis.center_of_mass.x + 60.0 * 2.995) / 2120.0;
        assert!(
            (f64::from(mp.local_com.x) - x).abs() < 1e-4,
            "{}",
            mp.local_com.x
        );
    }
}
