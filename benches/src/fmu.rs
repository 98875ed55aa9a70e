//! The two sides of the FMU's overhead benchmark (issue #32), shared by the criterion bench
//! (`benches/fmu.rs`) and the instruction counts (`benches/callgrind/`): a controller
//! stepping the TeslaModel3's default world through the Rust API, and a tool stepping the same
//! world through the FMU's `fmi2*` entry points. Each step sets the cruising speed (50 km/h)
//! and the steering angle, advances 10 ms and reads x, y, yaw, speed, yaw rate and engine
//! speed.
#![allow(
    unsafe_code,
    reason = "the FMU is called through its C entry points, as a tool calls it"
)]

use std::ffi::{CString, c_void};
use std::hint::black_box;
use std::path::PathBuf;

use sim::{SimError, Simulation, VehicleId, world_file};
use vehicle_fmu::fmi2::{
    fmi2DoStep, fmi2EnterInitializationMode, fmi2ExitInitializationMode, fmi2FreeInstance,
    fmi2GetReal, fmi2Instantiate, fmi2SetInteger, fmi2SetReal,
};
use vehicle_fmu::model_description::guid;
use vehicle_fmu::variables::{CONTROL_MODE, CRUISING_SPEED, STEERING_ANGLE};

/// The world both sides run.
pub const WORLD: &str = "basicTimeStep = 10\n[vehicle]\nmodel = \"TeslaModel3\"\n";
/// The cruising speed (m/s): 50 km/h.
const CRUISE_MS: f64 = 50.0 / 3.6;
/// The outputs read after each step: x, y, yaw, speed, yaw rate, engine speed.
const OUTPUTS: [u32; 6] = [100, 101, 105, 106, 109, 116];

/// The native side: a `Simulation` driven as a controller drives it.
pub struct NativeLoop {
    sim: Simulation,
    id: VehicleId,
}

impl NativeLoop {
    /// The world at rest.
    ///
    /// # Errors
    /// The world cannot be read or built (a fixture bug).
    pub fn new() -> Result<NativeLoop, String> {
        let description = world_file::parse_str("bench.toml", WORLD).map_err(|e| e.to_string())?;
        let (sim, _) = Simulation::from_description(&description).map_err(|e| e.to_string())?;
        let id = sim.car_ids().next().ok_or("no car")?;
        Ok(NativeLoop { sim, id })
    }

    /// One 10 ms step with the commands set and the outputs read.
    ///
    /// # Errors
    /// The engine's.
    pub fn step(&mut self) -> Result<(), SimError> {
        let d = self.sim.driver_mut(self.id)?;
        d.set_cruising_speed(black_box(CRUISE_MS * 3.6));
        d.set_steering_angle(black_box(0.0));
        self.sim.step()?;
        let t = self.sim.telemetry(self.id)?;
        black_box((
            t.state.position.x,
            t.state.position.y,
            t.state.roll_pitch_yaw.yaw,
            t.speed,
            t.state.yaw_rate,
            t.rpm,
        ));
        Ok(())
    }
}

/// The FMU side: an instance driven through the C entry points as a tool drives it.
pub struct FmuLoop {
    instance: *mut c_void,
    time: f64,
    resources: PathBuf,
}

impl FmuLoop {
    /// An initialised instance in speed control, its world in a temporary directory.
    ///
    /// # Errors
    /// The world cannot be written or the FMU refuses it (a fixture bug).
    pub fn new() -> Result<FmuLoop, String> {
        let resources = std::env::temp_dir().join(format!(
            "vehicle-fmu-bench-{}-{:p}",
            std::process::id(),
            &CRUISE_MS
        ));
        std::fs::create_dir_all(&resources).map_err(|e| e.to_string())?;
        std::fs::write(resources.join("world.toml"), WORLD).map_err(|e| e.to_string())?;
        let cstr = |s: String| CString::new(s).map_err(|e| e.to_string());
        let uri = cstr(format!("file://{}", resources.display()))?;
        let (name, token) = (cstr("bench".into())?, cstr(guid())?);
        // SAFETY: valid C strings; NULL callbacks (nothing is logged).
        let instance = unsafe {
            fmi2Instantiate(
                name.as_ptr(),
                1,
                token.as_ptr(),
                uri.as_ptr(),
                std::ptr::null(),
                0,
                0,
            )
        };
        if instance.is_null() {
            return Err("the FMU refused the bench world".into());
        }
        let ok = fmi2EnterInitializationMode(instance) == 0
            && fmi2ExitInitializationMode(instance) == 0
            // SAFETY: one reference, one value.
            && unsafe { fmi2SetInteger(instance, &CONTROL_MODE, 1, &0) } == 0;
        let l = FmuLoop {
            instance,
            time: 0.0,
            resources,
        };
        if ok {
            Ok(l)
        } else {
            Err("the FMU refused to initialise".into())
        }
    }

    /// One 10 ms step with the inputs set and the outputs read.
    ///
    /// # Errors
    /// A status other than `fmi2OK`.
    pub fn step(&mut self) -> Result<(), String> {
        let inputs = [CRUISING_SPEED, STEERING_ANGLE];
        let values = [black_box(CRUISE_MS), black_box(0.0)];
        let mut outputs = [0.0; OUTPUTS.len()];
        // SAFETY: arrays of the lengths passed; the instance is live.
        let status = unsafe {
            fmi2SetReal(self.instance, inputs.as_ptr(), 2, values.as_ptr())
                .max(fmi2DoStep(self.instance, self.time, 0.01, 1))
                .max(fmi2GetReal(
                    self.instance,
                    OUTPUTS.as_ptr(),
                    OUTPUTS.len(),
                    outputs.as_mut_ptr(),
                ))
        };
        self.time += 0.01;
        black_box(outputs);
        if status == 0 {
            Ok(())
        } else {
            Err(format!("status {status} at t = {} s", self.time))
        }
    }
}

impl Drop for FmuLoop {
    fn drop(&mut self) {
        // SAFETY: the instance was created in `new` and is freed once.
        unsafe { fmi2FreeInstance(self.instance) };
        let _ = std::fs::remove_dir_all(&self.resources);
    }
}
