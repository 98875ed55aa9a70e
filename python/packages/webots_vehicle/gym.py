"""gymnasium environments on the simulator (``pip install ./python[gym]``).

Importing this module registers three ids; gymnasium imports it itself for an id prefixed
with the module::

    import gymnasium as gym
    env = gym.make("webots_vehicle.gym:WebotsVehicle/LaneKeep-v0")
    # or: import webots_vehicle.gym; env = gym.make("WebotsVehicle/LaneKeep-v0")

* ``WebotsVehicle/LaneKeep-v0``: a BmwX5 on the highway's middle lane (three 3.75 m lanes, a
  straight into a 600 m curve) with a RoadSensor; keep the lane centre at speed. Terminated
  when the car leaves the road (more than a lane width from its lane centre, or off every
  road) or rolls over; truncated at the world's 40 s.
* ``WebotsVehicle/ACC-v0``: follow a lead car 50 m ahead that cruises at a speed drawn per
  episode (10 to 20 m/s) with a long-range radar; keep a 2 s time gap. Terminated when the
  cars touch; truncated at 60 s.
* ``WebotsVehicle/Track-v0``: drive round a circle of 30 m radius centred 30 m to the car's
  left at 10 m/s on flat ground. Terminated more than 10 m off the circle or rolled over;
  truncated at 60 s.

**Action** (all three): ``Box([-1, -1], [1, 1])``: ``action[0]`` the steering angle as a
share of 0.4 rad (positive turns right, as Webots'), ``action[1]`` the acceleration asked
of the cruise control as a share of 3 m/s² (its target speed, 0 to 40 m/s, moves by it each
control step; the driver library's SPEED mode reaches it).

**Observation**: a ``Dict``; every entry ``float32``:

* ``car``: speed (m/s, signed, forward > 0), yaw rate (rad/s), lateral velocity (m/s, left
  > 0), steering angle (rad), the cruise control's target speed (m/s);
* LaneKeep ``lane``: lateral offset from the lane centre (m, left > 0), heading error (rad),
  curvature here and 10 m ahead (1/m), lane width (m), and 1 on a road (0 off every road,
  where the others read 0);
* ACC ``radar``: up to 8 targets, nearest first, each distance (m), radial speed (m/s,
  > 0 receding), azimuth (rad, > 0 right) and received power (dBm), zero-padded, and
  ``radar_mask``: 1 for each real target;
* Track ``track``: signed distance from the circle (m, outside > 0) and heading error to the
  circle's tangent (rad).

**Reward**: by default the task's own (:func:`lane_keep_reward`, :func:`acc_reward`,
:func:`track_reward` say what it is), computed in Rust in the same call as the step.
``gym.make(id, reward_fn=f)`` replaces it: ``f(env, observation, action) -> float`` is then
called after each step with the observation returned and the action clipped to [-1, 1]
(float64). The three functions compute the default from an observation and an action (in
Rust too), so a replacement can build on it, e.g. ``lambda env, obs, a: lane_keep_reward(env,
obs, a) - 0.5 * a[1] ** 2``.

**Reset**: ``reset(seed=s)`` restores the world's snapshot taken when the environment was
built (bit for bit the same state), then places the car from the episode's random draw
(from ``seed``) or from ``options``: ``{"pose": (x, y, yaw), "speed": v}`` (m, rad, m/s;
ACC also ``"lead_speed"``). The same seed gives the same trajectory for the same actions.

**Where it runs**: the action, the basic time steps, the observation, the default reward
and the end of the episode are computed in Rust (``sim::vec_env::TaskEnv``), one extension
call per ``step()``; the environment's :attr:`VehicleEnv.sim` is the
:class:`~webots_vehicle.Simulation` it steps (it records no telemetry: read its cars'
``placement`` and devices). The observation's arrays are the caller's to keep (a copy per
step); ``copy=False`` (``gym.make(id, copy=False)``) returns the arrays the Rust core writes
into instead, which the next step or reset overwrites (no copy at all).

**Vectorised**: :class:`VectorEnv` (``gymnasium.make_vec(id, num_envs,
vectorization_mode="vector_entry_point")``) steps many copies of a world in Rust with one call
on numpy arrays, each with the same Rust code as the single environment: each copy equals the
single environment bit for bit.

**Render**: ``render_mode="rgb_array"``: a 128×128 top-down image centred on the car
(0.5 m per pixel, north up): the car red, other cars blue, the lane's markings (LaneKeep)
not drawn.
"""

import functools
import math
from pathlib import Path
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

import gymnasium
import gymnasium.vector
import numpy as np
from gymnasium import spaces
from gymnasium.utils import seeding
from gymnasium.vector.utils import batch_space

from webots_vehicle import _native
from webots_vehicle.simulation import Simulation

__all__ = [
    "ACCEnv",
    "LaneKeepEnv",
    "TrackEnv",
    "VectorEnv",
    "VehicleEnv",
    "acc_reward",
    "lane_keep_reward",
    "register_envs",
    "track_reward",
]

WORLDS = Path(__file__).resolve().parent / "worlds"

#: Radar targets in an observation.
RADAR_TARGETS = 8

#: An episode's start: x, y (m), yaw (rad), speed (m/s), the ACC lead's speed (m/s).
Start = Tuple[float, float, float, float, float]

RewardFn = Callable[["VehicleEnv", Dict[str, np.ndarray], np.ndarray], float]


def _box(n: int, bound: float) -> spaces.Box:
    return spaces.Box(-bound, bound, shape=(n,), dtype=np.float32)


def _layout(space: spaces.Dict) -> List[Tuple[str, slice, Tuple[int, ...]]]:
    """Each entry of an observation space: its key, its columns in the flat observation the
    Rust core writes (the space's keys in order) and its shape."""
    layout, column = [], 0
    for key, entry in space.spaces.items():
        width = int(np.prod(entry.shape))
        layout.append((key, slice(column, column + width), entry.shape))
        column += width
    return layout


def _yaw(rotation: Tuple[float, float, float, float]) -> float:
    """The heading (rad) of a Webots axis-angle rotation: its x axis projected on the ground
    (for ``render``; the observations' headings are computed in Rust)."""
    x, y, z, angle = rotation
    c, s = math.cos(angle), math.sin(angle)
    # First column of the rotation matrix (Rodrigues).
    fx = c + x * x * (1 - c)
    fy = y * x * (1 - c) + z * s
    return math.atan2(fy, fx)


class VehicleEnv(gymnasium.Env):
    """The common part of the three environments (see the module docs): a
    :class:`~webots_vehicle.Simulation` of a world file, :attr:`sim`, its car :attr:`car`
    driven by the action, stepped ``frame_skip`` basic time steps per action by the Rust
    core (``_native.GymEnv``)."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 25}

    #: The world file (in ``worlds/``), the task the Rust core runs on it ("LaneKeep", "ACC"
    #: or "Track") and the index of the agent's car (each environment gives its own, and its
    #: default reward).
    world = ""
    task = ""
    car_index = 0
    #: The task's default reward as a Python function of (env, observation, action): what
    #: ``step()`` returns without ``reward_fn`` (computed there in Rust in the step's call).
    default_reward_fn: RewardFn

    def __init__(
        self,
        render_mode: Optional[str] = None,
        reward_fn: Optional[RewardFn] = None,
        frame_skip: int = 4,
        copy: bool = True,
    ) -> None:
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', not {render_mode!r}")
        if frame_skip < 1:
            raise ValueError(f"frame_skip must be at least 1, not {frame_skip}")
        self.render_mode = render_mode
        self.frame_skip = int(frame_skip)
        # The steps record no telemetry: a training run keeps none.
        self.sim = Simulation(WORLDS / self.world, record=False)
        self.car = self.sim.cars[self.car_index]
        self.action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        self.observation_space = self.single_observation_space()
        # The Rust core writes each observation into `_buffer` and builds each step's
        # observation dict itself: new arrays, or with ``copy=False`` the entries' views of
        # `_buffer` (the space's keys in order, as the core lays them).
        layout = _layout(self.observation_space)
        self._buffer = np.zeros(layout[-1][1].stop, dtype=np.float32)
        entries = [
            (key, part.start, part.stop, list(shape), self._buffer[part].reshape(shape))
            for key, part, shape in layout
        ]
        self._core = _native.GymEnv(
            self.sim._core, self.task, self.frame_skip, self._buffer, entries, bool(copy)
        )
        self.dt = self._core.dt
        self.reward_fn = reward_fn
        self.metadata = dict(self.metadata, render_fps=round(1.0 / self.dt))
        # The state as loaded: every episode starts from it, bit for bit.
        self._start = self.sim.snapshot()
        #: Where this episode started: x, y (m), yaw (rad), speed (m/s), the ACC lead's speed.
        self.episode_start: Start = (0.0, 0.0, 0.0, 0.0, 0.0)

    # What each environment adds.
    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {}

    @classmethod
    def single_observation_space(cls) -> spaces.Dict:
        """The observation space (the same for every instance)."""
        return spaces.Dict({"car": _box(5, 100.0), **cls.extra_spaces()})

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        """x, y (m), yaw (rad), speed (m/s) of the car at an episode's start and the ACC
        lead's speed (m/s, 0 elsewhere): ``options``' ``pose``, ``speed`` (and
        ``lead_speed``), else drawn from ``rng`` (each environment draws its own; here at
        rest where the world file puts it). :class:`VectorEnv` draws with it too, so that a
        vector environment's episodes start where the single environment's do."""
        x, y, yaw = options.get("pose", (0.0, 0.0, 0.0))
        return float(x), float(y), float(yaw), float(options.get("speed", 0.0)), 0.0

    @property
    def touching(self) -> bool:
        """True while the agent's car touches another car."""
        return self._core.touching

    @property
    def reward_fn(self) -> Optional[RewardFn]:
        """The replacement reward, or None for the task's default (computed in Rust)."""
        return self._reward_fn

    @reward_fn.setter
    def reward_fn(self, fn: Optional[RewardFn]) -> None:
        self._reward_fn = fn
        # With the default reward and this class's own ``step``, ``env.step`` is the Rust
        # core's step itself: the Python frame in between is 0.15–0.25 µs of the 2 µs budget
        # (python/bench/gym_step.py). A replacement reward, or a subclass that overrides
        # ``step``, gets the Python method.
        if fn is None and type(self).step is VehicleEnv.step:
            self.step = self._core.step
        else:
            self.__dict__.pop("step", None)

    @property
    def copy(self) -> bool:
        """Whether observations are copies (True) or views the next step overwrites (the
        ``copy`` argument)."""
        return self._core.copy

    # The gymnasium API.
    def reset(
        self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None
    ) -> Tuple[Dict[str, np.ndarray], Dict[str, Any]]:
        super().reset(seed=seed)
        self.episode_start = self.draw_start(self.np_random, dict(options or {}))
        self.sim.restore(self._start)
        # The car placed, its cruise control at the start speed, one basic time step so that
        # the devices have their first sample.
        time = self._core.start(self.episode_start)
        return self._observation(), {"time": time}

    def step(
        self, action: np.ndarray
    ) -> Tuple[Dict[str, np.ndarray], float, bool, bool, Dict[str, Any]]:
        # The Rust core returns gymnasium's whole 5-tuple, observation dict and info included
        # (python/bench/gym_step.py measures the cost). Without a replacement reward the
        # instance's ``step`` is the core's own (see ``reward_fn``) and this is not called.
        if self.reward_fn is None:
            return self._core.step(action)
        obs, _, terminated, truncated, info = self._core.step(action)
        a = np.clip(np.asarray(action, dtype=np.float64), -1.0, 1.0)
        return obs, float(self.reward_fn(self, obs, a)), terminated, truncated, info

    def render(self) -> Optional[np.ndarray]:
        if self.render_mode != "rgb_array":
            return None
        size, scale = 128, 0.5  # pixels, m per pixel
        image = np.full((size, size, 3), 40, dtype=np.uint8)
        cx, cy, _ = self.car.placement.translation
        for i, car in enumerate(self.sim.cars):
            p = car.placement
            colour = (220, 40, 40) if i == self.car_index else (60, 90, 220)
            yaw = _yaw(p.rotation)
            # The car's footprint: 4.8 m by 1.9 m around a point 1.4 m ahead of its origin
            # (a BmwX5's outline), sampled at a quarter pixel.
            for u in np.arange(-1.0, 3.8, scale / 4):
                for v in np.arange(-0.95, 0.96, scale / 4):
                    wx = p.translation[0] + u * math.cos(yaw) - v * math.sin(yaw)
                    wy = p.translation[1] + u * math.sin(yaw) + v * math.cos(yaw)
                    col = int(round((wx - cx) / scale)) + size // 2
                    row = size // 2 - int(round((wy - cy) / scale))
                    if 0 <= row < size and 0 <= col < size:
                        image[row, col] = colour
        return image

    def _observation(self) -> Dict[str, np.ndarray]:
        """The last observation: copies of the buffer's entries, or the entries themselves
        with ``copy=False`` (see ``step``)."""
        return self._core.observation()


def _task_reward(task: str, env: "VehicleEnv", obs: Dict[str, np.ndarray], action) -> float:
    flat = np.concatenate([np.ravel(obs[key]) for key in env.observation_space.spaces])
    touching = task == "ACC" and env.touching
    a = np.asarray(action, dtype=np.float64).tolist()
    return _native.task_reward(task, flat.astype(np.float32).tolist(), a, touching)


def lane_keep_reward(env: "VehicleEnv", obs: Dict[str, np.ndarray], action: np.ndarray) -> float:
    """LaneKeep's default reward: the speed along the lane (m/s, up to 30) scaled to 1, less the
    lateral offset (m) squared, less a tenth of the steering action squared; −10 off the road
    (computed in Rust, ``sim::vec_env::Task::reward``)."""
    return _task_reward("LaneKeep", env, obs, action)


def acc_reward(env: "VehicleEnv", obs: Dict[str, np.ndarray], action: np.ndarray) -> float:
    """ACC's default reward: −(time gap − 2 s)² (the gap to the nearest target over the car's
    speed, at least 0.5 m/s, capped at 5 s), less a tenth of the acceleration action squared;
    −1 with no target in sight, −100 while the cars touch (``env.touching``; computed in
    Rust, ``sim::vec_env::Task::reward``)."""
    return _task_reward("ACC", env, obs, action)


def track_reward(env: "VehicleEnv", obs: Dict[str, np.ndarray], action: np.ndarray) -> float:
    """Track's default reward: 1 less the distance from the circle (m), less the speed error
    to 10 m/s (m/s) over 10 (computed in Rust, ``sim::vec_env::Task::reward``)."""
    return _task_reward("Track", env, obs, action)


class LaneKeepEnv(VehicleEnv):
    """``WebotsVehicle/LaneKeep-v0`` (see the module docs)."""

    world = "lane_keep.toml"
    task = "LaneKeep"
    default_reward_fn = staticmethod(lane_keep_reward)

    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {"lane": _box(6, 100.0)}

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        # The draws are made whether or not ``options`` overrides them, so that the random
        # sequence does not depend on the options.
        x, y, yaw = options.get(
            "pose", (20.0, -5.625 + rng.uniform(-0.5, 0.5), rng.uniform(-0.05, 0.05))
        )
        speed = options.get("speed", rng.uniform(10, 20))
        return float(x), float(y), float(yaw), float(speed), 0.0


class ACCEnv(VehicleEnv):
    """``WebotsVehicle/ACC-v0`` (see the module docs): the agent drives car 1 (the follower);
    the environment drives car 0 (the lead) at the episode's :attr:`lead_speed`."""

    world = "acc.toml"
    task = "ACC"
    default_reward_fn = staticmethod(acc_reward)
    car_index = 1

    @property
    def lead_speed(self) -> float:
        """The lead's speed this episode (m/s)."""
        return self.episode_start[4]

    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {
            "radar": spaces.Box(-1000.0, 1000.0, shape=(RADAR_TARGETS, 4), dtype=np.float32),
            "radar_mask": spaces.Box(0.0, 1.0, shape=(RADAR_TARGETS,), dtype=np.float32),
        }

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        x, y, yaw = options.get("pose", (0.0, 0.0, 0.0))
        lead_speed = options.get("lead_speed", rng.uniform(10.0, 20.0))
        return float(x), float(y), float(yaw), float(options.get("speed", 15.0)), float(lead_speed)


class TrackEnv(VehicleEnv):
    """``WebotsVehicle/Track-v0`` (see the module docs)."""

    world = "track.toml"
    task = "Track"
    default_reward_fn = staticmethod(track_reward)
    #: The speed the reward asks for and episodes start at (m/s).
    speed = 10.0

    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {"track": _box(2, 1000.0)}

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        x, y, yaw = options.get("pose", (0.0, rng.uniform(-1.0, 1.0), rng.uniform(-0.1, 0.1)))
        return float(x), float(y), float(yaw), float(options.get("speed", cls.speed)), 0.0


class VectorEnv(gymnasium.vector.VectorEnv):
    """``num_envs`` copies of one environment stepped together in Rust: one call takes the
    ``(num_envs, 2)`` action array and fills the observations, rewards and flags of all of
    them in place (numpy arrays, no Python object per environment), single-threaded.

    ``task`` is ``"LaneKeep"``, ``"ACC"`` or ``"Track"``; ``gymnasium.make_vec(id, num_envs,
    vectorization_mode="vector_entry_point")`` builds one for a registered id. Each copy runs
    the single environment's world, actions, observation, default reward and end of episode
    with the same Rust code (``sim::vec_env::TaskEnv``): copy ``i`` after ``reset(seed=s)``
    equals the single environment after ``reset(seed=s + i)`` given the same actions, bit for
    bit (its episodes start from its own random generator, seeded ``s + i``).

    **Autoreset**: gymnasium's ``NEXT_STEP`` mode (``metadata["autoreset_mode"]``): the step
    after a copy's episode ends resets it (its action ignored), returning its first
    observation with reward 0, not terminated and not truncated. ``reset(options=...)`` gives
    every copy the same options (as the single environment takes them); autoresets draw
    their starts.

    Differences from ``SyncVectorEnv`` over the single environments: the reward is the
    environment's default (compute another from the observations), ``infos`` is empty, and
    there is no rendering. ``copy=False`` returns the observation arrays the next step
    overwrites (no copy at all).
    """

    metadata = {"autoreset_mode": gymnasium.vector.AutoresetMode.NEXT_STEP, "render_modes": []}

    def __init__(self, task: str, num_envs: int = 1, frame_skip: int = 4, copy: bool = True) -> None:
        classes = {cls.task: cls for cls in (LaneKeepEnv, ACCEnv, TrackEnv)}
        if task not in classes:
            raise ValueError(f"task must be one of {sorted(classes)}, not {task!r}")
        if int(num_envs) < 1:
            raise ValueError(f"num_envs must be at least 1, not {num_envs}")
        if int(frame_skip) < 1:
            raise ValueError(f"frame_skip must be at least 1, not {frame_skip}")
        self.env_class = classes[task]
        self.num_envs = n = int(num_envs)
        self.copy = bool(copy)
        self.render_mode = None
        self._core = _native.VecSim(str(WORLDS / self.env_class.world), task, n, int(frame_skip))
        self.dt = self._core.dt
        self.single_action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        self.single_observation_space = self.env_class.single_observation_space()
        self.action_space = batch_space(self.single_action_space, n)
        self.observation_space = batch_space(self.single_observation_space, n)
        # The buffers the Rust side fills; the observation's entries are views of `_obs`.
        self._obs = np.zeros((n, self._core.observation_len), dtype=np.float32)
        self._actions = np.zeros((n, 2), dtype=np.float64)
        self._starts = np.zeros((n, 5), dtype=np.float64)
        self._rewards = np.zeros(n, dtype=np.float64)
        self._terminated = np.zeros(n, dtype=np.bool_)
        self._truncated = np.zeros(n, dtype=np.bool_)
        self._autoreset = np.zeros(n, dtype=np.bool_)
        self._views: Dict[str, np.ndarray] = {
            key: self._obs[:, part].reshape(n, *shape)
            for key, part, shape in _layout(self.single_observation_space)
        }
        self._rngs = [np.random.default_rng() for _ in range(n)]

    def _observation(self) -> Dict[str, np.ndarray]:
        if self.copy:
            return {k: v.copy() for k, v in self._views.items()}
        return dict(self._views)

    def reset(
        self,
        *,
        seed: Optional[Union[int, List[Optional[int]]]] = None,
        options: Optional[Dict[str, Any]] = None,
    ) -> Tuple[Dict[str, np.ndarray], Dict[str, Any]]:
        super().reset(seed=seed)
        if seed is None:
            seeds: List[Optional[int]] = [None] * self.num_envs
        elif isinstance(seed, int):
            seeds = [seed + i for i in range(self.num_envs)]
        else:
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ValueError(f"seed has {len(seeds)} values for {self.num_envs} environments")
        options = dict(options or {})
        for i, s in enumerate(seeds):
            if s is not None:
                self._rngs[i], _ = seeding.np_random(s)
            start = self.env_class.draw_start(self._rngs[i], options)
            self._core.reset(i, start, self._obs)
        self._autoreset[:] = False
        return self._observation(), {}

    def step(
        self, actions: np.ndarray
    ) -> Tuple[Dict[str, np.ndarray], np.ndarray, np.ndarray, np.ndarray, Dict[str, Any]]:
        a = np.asarray(actions, dtype=np.float64)
        if a.shape != self._actions.shape:
            raise ValueError(f"actions must have shape {self._actions.shape}, not {a.shape}")
        self._actions[...] = a
        for i in np.flatnonzero(self._autoreset):
            self._starts[i] = self.env_class.draw_start(self._rngs[i], {})
        self._core.step(
            self._actions,
            self._autoreset.view(np.uint8),
            self._starts,
            self._obs,
            self._rewards,
            self._terminated.view(np.uint8),
            self._truncated.view(np.uint8),
        )
        self._autoreset = self._terminated | self._truncated
        return (
            self._observation(),
            self._rewards.copy(),
            self._terminated.copy(),
            self._truncated.copy(),
            {},
        )


def register_envs() -> None:
    """Registers the three ids (importing this module does; again is harmless)."""
    for task, cls in (("LaneKeep", LaneKeepEnv), ("ACC", ACCEnv), ("Track", TrackEnv)):
        env_id = f"WebotsVehicle/{task}-v0"
        if env_id not in gymnasium.registry:
            gymnasium.register(
                id=env_id,
                entry_point=f"webots_vehicle.gym:{cls.__name__}",
                vector_entry_point=functools.partial(VectorEnv, task),
            )


register_envs()
