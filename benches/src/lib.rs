//! Shared pieces of the workspace benchmarks (`cargo bench -p benches`): the inputs every
//! benchmark starts from, rapier's ray-cast car used as the peer, and the reader of
//! criterion's results that prints ratios at the end of a run.
//!
//! The benchmarks themselves are in `benches/`: `kernels` (Ackermann angles, engine torque,
//! torque split), `simulation` (physics steps of the `sim` world beside the peer),
//! `callgrind` (instruction counts under valgrind), `replay` (what `replay.glb` adds to a
//! run), `sweep` (a sweep's cases per second on 1 and 2 threads) and `fmu` (an FMU step
//! against the native one), `energy` (what the road load, the air and the energy accounting
//! add to a car step). See `README.md` for the commands and the
//! latest numbers.
//!
//! ```
//! use benches::peer::{PeerParams, RayCastCar};
//! let mut car = RayCastCar::new(&PeerParams::default());
//! for _ in 0..100 {
//!     let force = car.cruise_force(5.0);
//!     car.step(force, 0.0);
//! }
//! assert!(car.forward_speed() > 3.0 && car.wheels_in_contact() == 4);
//! ```

pub mod control;
pub mod energy;
pub mod fixtures;
pub mod fmu;
pub mod peer;
pub mod report;
pub mod scenes;

// Compiles and runs the README's example as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctest;
