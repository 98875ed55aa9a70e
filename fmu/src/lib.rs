//! The car of a `vehicle-sim` world as an FMI 2.0 or 3.0 co-simulation FMU, for the model-
//! and software-in-the-loop tools ECU engineers use (FMPy, OpenModelica, Simulink, Dymola,
//! Silver …).
//!
//! * [`fmi2`] and [`fmi3`] hold the `fmi2*` and `fmi3*` C entry points of the one shared
//!   library (`vehicle_fmu.so`), over
//! * [`component`], what an instance handle points to (the instance and the tool's logger)
//!   and the guard every entry point runs behind, and [`states`], the FMU-state calls both
//!   versions share;
//! * [`instance::Instance`], one world, the co-simulation state machine, inputs and
//!   parameters, in safe Rust over the `sim` crate (the same engine as `vehicle-sim`, the C
//!   API and Python), and [`world`], how it reads and builds its world (the driven car and
//!   the traffic);
//! * [`journal`], the run as the inputs handed over and the steps run, which makes a state
//!   serialisable;
//! * [`variables`] lists the inputs (the driver's commands), outputs (what an ECU sees) and
//!   parameters (world-file keys), one table for the description and the accessors, and
//!   [`devices`] the outputs of the car's sensors, which depend on the world;
//! * [`model_description`] writes `modelDescription.xml` for either version;
//! * [`package`] writes the `.fmu` archive, for the `vehicle-fmu` command.
//!
//! Frame and units as everywhere in the project: x forward, y left, z up; rad, m, m/s, N·m, W;
//! positive steering turns right, as in Webots.

pub mod component;
pub mod devices;
pub mod fmi2;
pub mod fmi3;
pub mod instance;
pub mod journal;
pub mod model_description;
pub mod package;
pub mod states;
pub mod variables;
pub mod world;
