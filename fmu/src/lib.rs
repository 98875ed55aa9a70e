//! The car of a `vehicle-sim` world as an FMI 2.0 co-simulation FMU, for the model- and
//! software-in-the-loop tools ECU engineers use (FMPy, OpenModelica, Simulink, Dymola,
//! Silver …).
//!
//! * [`fmi2`] holds the `fmi2*` C entry points of the shared library (`vehicle_fmu.so`),
//!   over
//! * [`instance::Instance`], one world, the FMI state machine, inputs and parameters, in safe
//!   Rust over the `sim` crate (the same engine as `vehicle-sim`, the C API and Python);
//! * [`variables`] lists the inputs (the driver's commands), outputs (what an ECU sees) and
//!   parameters (world-file keys), one table for the description and the accessors;
//! * [`model_description`] writes `modelDescription.xml`;
//! * [`package`] writes the `.fmu` archive, for the `vehicle-fmu` command.
//!
//! Frame and units as everywhere in the project: x forward, y left, z up; rad, m, m/s, N·m, W;
//! positive steering turns right, as in Webots.

pub mod fmi2;
pub mod instance;
pub mod model_description;
pub mod package;
pub mod variables;
