//! `_native.GymEnv`: `sim::vec_env::TaskEnv` on a `webots_vehicle.Simulation`, for the single
//! environments of `webots_vehicle.gym` (`LaneKeepEnv`, `ACCEnv`, `TrackEnv`).
//!
//! The Python `step()` makes one call here: the action in (a numpy array through the buffer
//! protocol, or any two numbers), the observation written into the numpy array given at
//! construction (held open, so no buffer is acquired per step), reward, flags and time
//! returned as one tuple. The simulation stays the Python `Simulation`'s own, so the
//! environment's `sim` shows the state the steps reach.

use pyo3::buffer::PyBuffer;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use sim::vec_env::{ACTION_LEN, Task, TaskEnv, VecEnvError};

use crate::simulation::Simulation;
use crate::vec_env::{START_LEN, batch_error, start_of};

/// One gym environment on a `Simulation`: see the module docs.
#[pyclass(module = "webots_vehicle._native", unsendable)]
pub(crate) struct GymEnv {
    sim: Py<Simulation>,
    env: TaskEnv,
    observation: Vec<f32>,
    /// The numpy array the observations are written into.
    out: PyBuffer<f32>,
}

/// The task named `name` ("LaneKeep", "ACC" or "Track"), or ValueError.
pub(crate) fn task_of(name: &str) -> PyResult<Task> {
    name.parse()
        .map_err(|e: sim::vec_env::UnknownTask| PyValueError::new_err(e.to_string()))
}

/// Errors of one environment: those of a batch, an action named as the single action.
fn env_error(e: VecEnvError) -> PyErr {
    match e {
        VecEnvError::Action { index, value, .. } => {
            PyValueError::new_err(format!("action[{index}] must be finite, not {value}"))
        }
        other => batch_error(other),
    }
}

/// `action` as two numbers: a float32 or float64 buffer of two values (numpy arrays, the
/// fast path), else any sequence of two numbers.
fn action_of(action: &Bound<'_, PyAny>) -> PyResult<[f64; ACTION_LEN]> {
    let py = action.py();
    let wrong = |n: usize| {
        PyValueError::new_err(format!(
            "the action must have {ACTION_LEN} values (steering, acceleration), not {n}"
        ))
    };
    if let Ok(buffer) = PyBuffer::<f32>::get(action) {
        let mut a = [0.0f32; ACTION_LEN];
        if buffer.item_count() != ACTION_LEN {
            return Err(wrong(buffer.item_count()));
        }
        buffer.copy_to_slice(py, &mut a)?;
        return Ok(a.map(f64::from));
    }
    if let Ok(buffer) = PyBuffer::<f64>::get(action) {
        let mut a = [0.0f64; ACTION_LEN];
        if buffer.item_count() != ACTION_LEN {
            return Err(wrong(buffer.item_count()));
        }
        buffer.copy_to_slice(py, &mut a)?;
        return Ok(a);
    }
    let values: Vec<f64> = action.extract()?;
    <[f64; ACTION_LEN]>::try_from(values.as_slice()).map_err(|_| wrong(values.len()))
}

#[pymethods]
impl GymEnv {
    /// `task` ("LaneKeep", "ACC" or "Track") on `simulation` (the core of a
    /// `webots_vehicle.Simulation`, as loaded), `frame_skip` basic time steps per action; the
    /// observations are written into `observation` (a C-contiguous float32 numpy array of
    /// `observation_len` values, which stays open for writing while this lives).
    #[new]
    fn new(
        py: Python<'_>,
        simulation: Py<Simulation>,
        task: &str,
        frame_skip: u32,
        observation: PyBuffer<f32>,
    ) -> PyResult<Self> {
        let task = task_of(task)?;
        let env = {
            let sim = simulation.bind(py).try_borrow()?;
            TaskEnv::new(sim.engine(), task, frame_skip).map_err(env_error)?
        };
        let m = task.observation_len();
        if observation.readonly() || !observation.is_c_contiguous() || observation.item_count() != m
        {
            return Err(PyValueError::new_err(format!(
                "observation must be a writable C-contiguous float32 array of {m} values"
            )));
        }
        Ok(GymEnv {
            sim: simulation,
            env,
            observation: vec![0.0; m],
            out: observation,
        })
    }

    /// Values in an observation.
    #[getter]
    fn observation_len(&self) -> usize {
        self.env.task().observation_len()
    }

    /// Simulated time per step (s).
    #[getter]
    fn dt(&self) -> f64 {
        self.env.dt()
    }

    /// Starts an episode from `start` (x m, y m, yaw rad, speed m/s, lead speed m/s) on the
    /// simulation, which the caller has restored to the environment's start; writes the first
    /// observation; returns the simulated time (s).
    fn start(&mut self, py: Python<'_>, start: [f64; START_LEN]) -> PyResult<f64> {
        let mut sim = self.sim.bind(py).try_borrow_mut()?;
        let engine = sim.engine_mut();
        self.env
            .start(engine, &start_of(&start), &mut self.observation)
            .map_err(env_error)?;
        let time = engine.world().time();
        self.out.copy_from_slice(py, &self.observation)?;
        Ok(time)
    }

    /// One step with `action` (steering, acceleration; clipped to −1 to 1): writes the
    /// observation, returns (default reward, terminated, truncated, simulated time s).
    fn step(
        &mut self,
        py: Python<'_>,
        action: &Bound<'_, PyAny>,
    ) -> PyResult<(f64, bool, bool, f64)> {
        let action = action_of(action)?;
        let mut sim = self.sim.bind(py).try_borrow_mut()?;
        let engine = sim.engine_mut();
        let outcome = self
            .env
            .step(engine, action, &mut self.observation)
            .map_err(env_error)?;
        let time = engine.world().time();
        self.out.copy_from_slice(py, &self.observation)?;
        Ok((outcome.reward, outcome.terminated, outcome.truncated, time))
    }

    /// True while the agent's car touches another car.
    #[getter]
    fn touching(&self, py: Python<'_>) -> PyResult<bool> {
        let sim = self.sim.bind(py).try_borrow()?;
        self.env
            .touching(sim.engine())
            .map_err(|e| crate::simulation::sim_error(&e))
    }

    /// Runs `steps` steps of `sim::vec_env::TaskEnv::step` with `action` (the Rust step alone:
    /// no action conversion, no copy into the numpy array) and returns the wall time they took
    /// (s): `python/bench/gym_step.py` times the same steps through `step()` on the same
    /// environment, and the difference is the cost of the Python and PyO3 layers.
    fn bench_steps(
        &mut self,
        py: Python<'_>,
        steps: u64,
        action: [f64; ACTION_LEN],
    ) -> PyResult<f64> {
        let mut sim = self.sim.bind(py).try_borrow_mut()?;
        let engine = sim.engine_mut();
        let begin = std::time::Instant::now();
        for _ in 0..steps {
            self.env
                .step(engine, action, &mut self.observation)
                .map_err(env_error)?;
        }
        Ok(begin.elapsed().as_secs_f64())
    }
}

/// The default reward of `task` for `observation` (one flat float32 row) after `action`
/// (clipped to −1 to 1), the agent's car `touching` another or not: `sim::vec_env::Task::reward`.
#[pyfunction]
fn task_reward(
    task: &str,
    observation: Vec<f32>,
    action: [f64; ACTION_LEN],
    touching: bool,
) -> PyResult<f64> {
    let action = action.map(|a| a.clamp(-1.0, 1.0));
    let (reward, _) = task_of(task)?
        .reward(&observation, action, touching)
        .map_err(env_error)?;
    Ok(reward)
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<GymEnv>()?;
    m.add_function(wrap_pyfunction!(task_reward, m)?)
}
