//! The wheels' driveline losses for one step: Webots' viscous `wheelsDampingConstant`, or the
//! road-load set of [`VehicleSpec::road_load`](super::VehicleSpec::road_load) (a constant and
//! a viscous drag, [`vehicle_model::RoadLoad`]).
//!
//! Why on the wheel's spin: the tyre then carries the loss to the road as a real one does,
//! and one path serves both mountings. The constant drag joins the brake torque where the
//! tyre's rolling resistance does, once the wheel's contact is set up (`wheels.rs`: after the
//! choice of sub-stepping a braked wheel, which it must not make of a rolling one); the
//! contact solve applies it as friction on the spin, which stops a wheel and never reverses
//! it. The viscous drag takes the place of Webots' damping in the spin's implicit step.

use super::Vehicle;

impl Vehicle {
    /// The viscous drag of each wheel's spin (N·m·s/rad): the road-load set's, else Webots'
    /// `wheelsDampingConstant`.
    pub(super) fn viscous_wheel_drag(&self) -> f64 {
        self.spec
            .road_load
            .map_or(self.spec.wheels_damping, |r| r.viscous_drag)
    }

    /// The constant drag torque of each wheel (N·m, ≥ 0): the road-load set's, 0 without one
    /// (Webots has none).
    pub(super) fn constant_wheel_drag(&self) -> f64 {
        self.spec.road_load.map_or(0.0, |r| r.drag_torque)
    }
}
