//! `_native.GymEnv`: `sim::vec_env::TaskEnv` on a `webots_vehicle.Simulation`, for the single
//! environments of `webots_vehicle.gym` (`LaneKeepEnv`, `ACCEnv`, `TrackEnv`).
//!
//! The Python `step()` is this one call: the action in (a float32 or float64 numpy array of
//! two values, or any two numbers), gymnasium's whole 5-tuple out — the observation dict
//! (new numpy arrays made here, or the views of the array the core writes into), the
//! reward, the two flags and the info dict `{"time": t}`. Building the tuple here rather
//! than in Python is what keeps `step()` within 2 µs of the Rust step (issue #33; each
//! Python-level `copy()`, dict and tuple cost 0.1–0.3 µs). The observation is also written
//! into the numpy array given at construction (held open, so no buffer is acquired per
//! step). The simulation stays the Python `Simulation`'s own, so the environment's `sim`
//! shows the state the steps reach.

use numpy::{PyArray1, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::buffer::PyBuffer;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString, PyTuple};

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
    /// The observation dict's entries in the space's order.
    entries: Vec<Entry>,
    /// True: each observation's arrays are new (the caller's to keep); false: the entries'
    /// views of `out`, which the next step overwrites.
    copy: bool,
    /// The info dict's key, interned once.
    time_key: Py<PyString>,
}

/// One entry of the observation dict: its key, its values' place in the flat observation and
/// its shape, and its view of the output array.
struct Entry {
    key: Py<PyString>,
    start: usize,
    end: usize,
    /// Its shape when it has more than one dimension (reshaped after the copy), else None.
    shape: Option<Vec<usize>>,
    view: Py<PyAny>,
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

/// `action` as two numbers: a one-dimensional float32 or float64 numpy array of two values
/// (the fast path: a type check, where a buffer request of the wrong type raises and clears
/// an exception, about 1 µs), else any float32 or float64 buffer of two values (other shapes),
/// else any sequence of two numbers.
fn action_of(action: &Bound<'_, PyAny>) -> PyResult<[f64; ACTION_LEN]> {
    if let Ok(array) = action.cast::<PyArray1<f32>>() {
        return pair(array).map(|a| a.map(f64::from));
    }
    if let Ok(array) = action.cast::<PyArray1<f64>>() {
        return pair(array);
    }
    let py = action.py();
    if let Ok(buffer) = PyBuffer::<f32>::get(action) {
        let mut a = [0.0f32; ACTION_LEN];
        if buffer.item_count() != ACTION_LEN {
            return Err(wrong_length(buffer.item_count()));
        }
        buffer.copy_to_slice(py, &mut a)?;
        return Ok(a.map(f64::from));
    }
    if let Ok(buffer) = PyBuffer::<f64>::get(action) {
        let mut a = [0.0f64; ACTION_LEN];
        if buffer.item_count() != ACTION_LEN {
            return Err(wrong_length(buffer.item_count()));
        }
        buffer.copy_to_slice(py, &mut a)?;
        return Ok(a);
    }
    let values: Vec<f64> = action.extract()?;
    <[f64; ACTION_LEN]>::try_from(values.as_slice()).map_err(|_| wrong_length(values.len()))
}

/// The two values of a one-dimensional array, or ValueError naming its length.
fn pair<T: numpy::Element + Copy>(array: &Bound<'_, PyArray1<T>>) -> PyResult<[T; ACTION_LEN]> {
    match (array.len(), array.get_owned(0), array.get_owned(1)) {
        (ACTION_LEN, Some(a), Some(b)) => Ok([a, b]),
        (n, ..) => Err(wrong_length(n)),
    }
}

fn wrong_length(n: usize) -> PyErr {
    PyValueError::new_err(format!(
        "the action must have {ACTION_LEN} values (steering, acceleration), not {n}"
    ))
}

impl GymEnv {
    /// The observation dict of the last written observation: new arrays, or the views.
    fn observation_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for e in &self.entries {
            if self.copy {
                let array = PyArray1::from_slice(py, &self.observation[e.start..e.end]);
                match &e.shape {
                    Some(shape) => {
                        dict.set_item(e.key.bind(py), array.reshape(shape.as_slice())?)?
                    }
                    None => dict.set_item(e.key.bind(py), array)?,
                }
            } else {
                dict.set_item(e.key.bind(py), e.view.bind(py))?;
            }
        }
        Ok(dict)
    }
}

#[pymethods]
impl GymEnv {
    /// `task` ("LaneKeep", "ACC" or "Track") on `simulation` (the core of a
    /// `webots_vehicle.Simulation`, as loaded), `frame_skip` basic time steps per action; the
    /// observations are written into `observation` (a C-contiguous float32 numpy array of
    /// `observation_len` values, which stays open for writing while this lives); `layout`
    /// gives each entry of the observation dict in order: its key, its first and one-past-last
    /// value in the flat observation, its shape and its view of `observation`; `copy`: whether
    /// `step()` returns new arrays (true) or those views.
    #[new]
    #[allow(clippy::type_complexity)]
    fn new(
        py: Python<'_>,
        simulation: Py<Simulation>,
        task: &str,
        frame_skip: u32,
        observation: PyBuffer<f32>,
        layout: Vec<(Py<PyString>, usize, usize, Vec<usize>, Py<PyAny>)>,
        copy: bool,
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
        let mut entries = Vec::with_capacity(layout.len());
        let mut next = 0;
        for (key, start, end, shape, view) in layout {
            let count: usize = shape.iter().product();
            if start != next || end < start || end - start != count || end > m {
                return Err(PyValueError::new_err(format!(
                    "layout entry {} ({start}..{end}, shape {shape:?}) does not follow \
                     {next} in an observation of {m} values",
                    key.bind(py)
                )));
            }
            next = end;
            entries.push(Entry {
                key,
                start,
                end,
                shape: (shape.len() > 1).then_some(shape),
                view,
            });
        }
        if next != m {
            return Err(PyValueError::new_err(format!(
                "the layout covers {next} of the observation's {m} values"
            )));
        }
        Ok(GymEnv {
            sim: simulation,
            env,
            observation: vec![0.0; m],
            out: observation,
            entries,
            copy,
            time_key: PyString::intern(py, "time").unbind(),
        })
    }

    /// Whether `step()` returns new arrays (true) or the views the next step overwrites.
    #[getter]
    fn copy(&self) -> bool {
        self.copy
    }

    /// The last observation as the observation dict (see `copy`).
    fn observation<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.observation_dict(py)
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

    /// One step with `action` (steering, acceleration; clipped to −1 to 1): gymnasium's
    /// (observation dict, default reward, terminated, truncated, {"time": simulated time s}).
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        action: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let action = action_of(action)?;
        let mut sim = self.sim.bind(py).try_borrow_mut()?;
        let engine = sim.engine_mut();
        let outcome = self
            .env
            .step(engine, action, &mut self.observation)
            .map_err(env_error)?;
        let time = engine.world().time();
        drop(sim);
        self.out.copy_from_slice(py, &self.observation)?;
        let info = PyDict::new(py);
        info.set_item(self.time_key.bind(py), time)?;
        let observation = self.observation_dict(py)?;
        (
            observation,
            outcome.reward,
            outcome.terminated,
            outcome.truncated,
            info,
        )
            .into_pyobject(py)
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
