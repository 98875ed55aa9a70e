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

**Reward**: a replaceable function ``reward_fn(env, observation, action) -> float``, given to
the constructor (``gym.make(id, reward_fn=...)``); the defaults are
:func:`lane_keep_reward`, :func:`acc_reward` and :func:`track_reward`.

**Reset**: ``reset(seed=s)`` restores the world's snapshot taken when the environment was
built (bit for bit the same state), then places the car from the episode's random draw
(from ``seed``) or from ``options``: ``{"pose": (x, y, yaw), "speed": v}`` (m, rad, m/s;
ACC also ``"lead_speed"``). The same seed gives the same trajectory for the same actions.

**Vectorised**: :class:`VectorEnv` (``gymnasium.make_vec(id, num_envs,
vectorization_mode="vector_entry_point")``) steps many copies of a world in Rust with one call
on numpy arrays; each copy equals the single environment bit for bit.

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

#: Steering angle of a full action (rad).
MAX_STEERING = 0.4
#: Acceleration of a full action (m/s²).
MAX_ACCELERATION = 3.0
#: Highest cruise target (m/s).
MAX_SPEED = 40.0
#: Radar targets in an observation.
RADAR_TARGETS = 8

#: An episode's start: x, y (m), yaw (rad), speed (m/s), the ACC lead's speed (m/s).
Start = Tuple[float, float, float, float, float]

RewardFn = Callable[["VehicleEnv", Dict[str, np.ndarray], np.ndarray], float]


def _box(n: int, bound: float) -> spaces.Box:
    return spaces.Box(-bound, bound, shape=(n,), dtype=np.float32)


def _vector(values: List[float], bound: float) -> np.ndarray:
    """``values`` as float32, NaN as 0, within ±``bound`` (the space's limits)."""
    a = np.nan_to_num(np.asarray(values, dtype=np.float64), nan=0.0, posinf=bound, neginf=-bound)
    return np.clip(a, -bound, bound).astype(np.float32)


def _yaw(rotation: Tuple[float, float, float, float]) -> float:
    """The heading (rad) of a Webots axis-angle rotation: its x axis projected on the ground."""
    x, y, z, angle = rotation
    c, s = math.cos(angle), math.sin(angle)
    # First column of the rotation matrix (Rodrigues).
    fx = c + x * x * (1 - c)
    fy = y * x * (1 - c) + z * s
    return math.atan2(fy, fx)


class VehicleEnv(gymnasium.Env):
    """The common part of the three environments (see the module docs): a
    :class:`~webots_vehicle.Simulation` of a world file, its car ``car`` driven by the
    action, stepped ``frame_skip`` basic time steps per action."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 25}

    #: The world file (in ``worlds/``), the index of the agent's car, and the default reward
    #: (each environment gives its own).
    world = ""
    car_index = 0
    default_reward_fn: RewardFn

    def __init__(
        self,
        render_mode: Optional[str] = None,
        reward_fn: Optional[RewardFn] = None,
        frame_skip: int = 4,
    ) -> None:
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', not {render_mode!r}")
        if frame_skip < 1:
            raise ValueError(f"frame_skip must be at least 1, not {frame_skip}")
        self.render_mode = render_mode
        self.reward_fn: RewardFn = reward_fn or type(self).default_reward_fn
        self.frame_skip = int(frame_skip)
        # Observations read the car's last state (O(1)); a training run keeps no telemetry.
        self.sim = Simulation(WORLDS / self.world, record=False)
        self.car = self.sim.cars[self.car_index]
        self.dt = self.sim.basic_time_step * self.frame_skip / 1000.0
        self.metadata = dict(self.metadata, render_fps=round(1.0 / self.dt))
        # The state as loaded: every episode starts from it, bit for bit.
        self._start = self.sim.snapshot()
        self._rest_height = self.car.placement.translation[2]
        self._target = 0.0
        self.action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        self.observation_space = self.single_observation_space()

    # What each environment adds.
    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {}

    @classmethod
    def single_observation_space(cls) -> spaces.Dict:
        """The observation space (the same for every instance)."""
        return spaces.Dict({"car": _box(5, 100.0), **cls.extra_spaces()})

    def extra_observation(self) -> Dict[str, np.ndarray]:
        return {}

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        """x, y (m), yaw (rad), speed (m/s) of the car at an episode's start and the ACC
        lead's speed (m/s, 0 elsewhere): ``options``' ``pose``, ``speed`` (and
        ``lead_speed``), else drawn from ``rng`` (each environment draws its own; here at
        rest where the world file puts it). :class:`VectorEnv` draws with it too, so that a
        vector environment's episodes start where the single environment's do."""
        x, y, yaw = options.get("pose", (0.0, 0.0, 0.0))
        return float(x), float(y), float(yaw), float(options.get("speed", 0.0)), 0.0

    def is_terminated(self, obs: Dict[str, np.ndarray]) -> bool:
        return False

    def setup_episode(self, start: Start) -> None:
        """Anything else an episode starts with (the ACC lead's speed)."""

    # The gymnasium API.
    def reset(
        self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None
    ) -> Tuple[Dict[str, np.ndarray], Dict[str, Any]]:
        super().reset(seed=seed)
        options = dict(options or {})
        self.sim.restore(self._start)
        start = self.draw_start(self.np_random, options)
        x, y, yaw, speed, _ = start
        self.car.set_pose([x, y, self._rest_height], [0.0, 0.0, 1.0, yaw])
        self.car.set_velocity([speed * math.cos(yaw), speed * math.sin(yaw), 0.0])
        self._target = float(np.clip(speed, 0.0, MAX_SPEED))
        self.car.set_cruising_speed(self._target * 3.6)
        self.car.set_steering_angle(0.0)
        self.setup_episode(start)
        # One step, so that the devices have their first sample.
        self.sim.step(1)
        return self._observation(), {"time": self.sim.time}

    def step(
        self, action: np.ndarray
    ) -> Tuple[Dict[str, np.ndarray], float, bool, bool, Dict[str, Any]]:
        a = np.clip(np.asarray(action, dtype=np.float64), -1.0, 1.0)
        if not np.all(np.isfinite(a)):
            raise ValueError(f"the action must be finite, not {action!r}")
        self.car.set_steering_angle(float(a[0]) * MAX_STEERING)
        self._target = float(
            np.clip(self._target + a[1] * MAX_ACCELERATION * self.dt, 0.0, MAX_SPEED)
        )
        self.car.set_cruising_speed(self._target * 3.6)
        going = self.sim.step(self.frame_skip)
        obs = self._observation()
        terminated = self._rolled_over() or self.is_terminated(obs)
        reward = float(self.reward_fn(self, obs, a))
        return obs, reward, terminated, not going, {"time": self.sim.time}

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

    # Helpers.
    def _observation(self) -> Dict[str, np.ndarray]:
        p = self.car.placement
        yaw = _yaw(p.rotation)
        vx, vy, _ = p.velocity
        forward = vx * math.cos(yaw) + vy * math.sin(yaw)
        lateral = -vx * math.sin(yaw) + vy * math.cos(yaw)
        state = self.car.state or {}
        steering = state.get("steering_rad", 0.0)
        car = _vector([forward, p.angular_velocity[2], lateral, steering, self._target], 100.0)
        return {"car": car, **self.extra_observation()}

    def _rolled_over(self) -> bool:
        x, y, z, angle = self.car.placement.rotation
        # The car's up axis tilted more than 60° from vertical.
        c = math.cos(angle)
        up_z = c + z * z * (1 - c)
        return up_z < 0.5


def lane_keep_reward(env: "VehicleEnv", obs: Dict[str, np.ndarray], action: np.ndarray) -> float:
    """Speed along the lane (m/s, up to 30) scaled to 1, less the lateral offset (m) squared,
    less a tenth of the steering action squared; −10 off the road."""
    offset, heading, _, _, _, on_road = (float(v) for v in obs["lane"])
    if on_road < 0.5:
        return -10.0
    speed = float(obs["car"][0]) * math.cos(heading)
    return min(speed, 30.0) / 30.0 - offset * offset - 0.1 * float(action[0]) ** 2


def acc_reward(env: "VehicleEnv", obs: Dict[str, np.ndarray], action: np.ndarray) -> float:
    """−(time gap − 2 s)² (the gap to the nearest target over the car's speed, capped at
    5 s), less a tenth of the acceleration action squared; −1 with no target in sight, −100
    for touching the lead."""
    if env.sim._core.touching(env.car_index):
        return -100.0
    mask = obs["radar_mask"]
    if mask[0] < 0.5:
        return -1.0
    speed = max(float(obs["car"][0]), 0.5)
    gap = min(float(obs["radar"][0][0]) / speed, 5.0)
    return -((gap - 2.0) ** 2) - 0.1 * float(action[1]) ** 2


def track_reward(env: "VehicleEnv", obs: Dict[str, np.ndarray], action: np.ndarray) -> float:
    """1 less the distance from the circle (m), less the speed error to 10 m/s (m/s) over 10."""
    off, _ = (float(v) for v in obs["track"])
    return 1.0 - abs(off) - abs(float(obs["car"][0]) - TrackEnv.speed) / 10.0


class LaneKeepEnv(VehicleEnv):
    """``WebotsVehicle/LaneKeep-v0`` (see the module docs)."""

    world = "lane_keep.toml"
    default_reward_fn = staticmethod(lane_keep_reward)

    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {"lane": _box(6, 100.0)}

    def extra_observation(self) -> Dict[str, np.ndarray]:
        r = self.sim._core.road_reading(self.car_index)
        if r is None or r[0] < 0 or not math.isfinite(r[3]):
            return {"lane": np.zeros(6, dtype=np.float32)}
        return {"lane": _vector([r[3], r[4], r[5], r[6], r[11], 1.0], 100.0)}

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        # The draws are made whether or not ``options`` overrides them, so that the random
        # sequence does not depend on the options.
        x, y, yaw = options.get(
            "pose", (20.0, -5.625 + rng.uniform(-0.5, 0.5), rng.uniform(-0.05, 0.05))
        )
        speed = options.get("speed", rng.uniform(10, 20))
        return float(x), float(y), float(yaw), float(speed), 0.0

    def is_terminated(self, obs: Dict[str, np.ndarray]) -> bool:
        offset, _, _, _, width, on_road = (float(v) for v in obs["lane"])
        return on_road < 0.5 or abs(offset) > width


class ACCEnv(VehicleEnv):
    """``WebotsVehicle/ACC-v0`` (see the module docs): the agent drives car 1 (the follower);
    the environment drives car 0 (the lead) at the episode's ``lead_speed``."""

    world = "acc.toml"
    car_index = 1
    default_reward_fn = staticmethod(acc_reward)
    #: The lead's speed this episode (m/s).
    lead_speed = 0.0

    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {
            "radar": spaces.Box(-1000.0, 1000.0, shape=(RADAR_TARGETS, 4), dtype=np.float32),
            "radar_mask": spaces.Box(0.0, 1.0, shape=(RADAR_TARGETS,), dtype=np.float32),
        }

    def extra_observation(self) -> Dict[str, np.ndarray]:
        targets = sorted(self.sim._core.radar_targets(self.car_index))[:RADAR_TARGETS]
        radar = np.zeros((RADAR_TARGETS, 4), dtype=np.float32)
        mask = np.zeros(RADAR_TARGETS, dtype=np.float32)
        for i, (distance, power, speed, azimuth) in enumerate(targets):
            radar[i] = _vector([distance, speed, azimuth, power], 1000.0)
            mask[i] = 1.0
        return {"radar": radar, "radar_mask": mask}

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        x, y, yaw = options.get("pose", (0.0, 0.0, 0.0))
        lead_speed = options.get("lead_speed", rng.uniform(10.0, 20.0))
        return float(x), float(y), float(yaw), float(options.get("speed", 15.0)), float(lead_speed)

    def setup_episode(self, start: Start) -> None:
        self.lead_speed = start[4]
        lead = self.sim.cars[0]
        lead.set_velocity([self.lead_speed, 0.0, 0.0])
        lead.set_cruising_speed(self.lead_speed * 3.6)

    def is_terminated(self, obs: Dict[str, np.ndarray]) -> bool:
        return bool(self.sim._core.touching(self.car_index))


class TrackEnv(VehicleEnv):
    """``WebotsVehicle/Track-v0`` (see the module docs)."""

    world = "track.toml"
    #: The circle's radius (m), centre (m) and speed (m/s).
    radius = 30.0
    centre = (0.0, 30.0)
    speed = 10.0
    default_reward_fn = staticmethod(track_reward)

    @classmethod
    def extra_spaces(cls) -> Dict[str, spaces.Space]:
        return {"track": _box(2, 1000.0)}

    def extra_observation(self) -> Dict[str, np.ndarray]:
        p = self.car.placement
        dx, dy = p.translation[0] - self.centre[0], p.translation[1] - self.centre[1]
        off = math.hypot(dx, dy) - self.radius
        # Counter-clockwise round the centre: the tangent is the radius turned by +90°.
        tangent = math.atan2(dy, dx) + math.pi / 2
        error = (_yaw(p.rotation) - tangent + math.pi) % (2 * math.pi) - math.pi
        return {"track": _vector([off, error], 1000.0)}

    @classmethod
    def draw_start(cls, rng: np.random.Generator, options: Dict[str, Any]) -> Start:
        x, y, yaw = options.get("pose", (0.0, rng.uniform(-1.0, 1.0), rng.uniform(-0.1, 0.1)))
        return float(x), float(y), float(yaw), float(options.get("speed", cls.speed)), 0.0

    def is_terminated(self, obs: Dict[str, np.ndarray]) -> bool:
        return abs(float(obs["track"][0])) > 10.0


class VectorEnv(gymnasium.vector.VectorEnv):
    """``num_envs`` copies of one environment stepped together in Rust: one call takes the
    ``(num_envs, 2)`` action array and fills the observations, rewards and flags of all of
    them in place (numpy arrays, no Python object per environment), single-threaded.

    ``task`` is ``"LaneKeep"``, ``"ACC"`` or ``"Track"``; ``gymnasium.make_vec(id, num_envs,
    vectorization_mode="vector_entry_point")`` builds one for a registered id. Each copy runs
    the single environment's world, actions, observation, default reward and end of episode
    with the same floating-point operations: copy ``i`` after ``reset(seed=s)`` equals the
    single environment after ``reset(seed=s + i)`` given the same actions, bit for bit
    (its episodes start from its own random generator, seeded ``s + i``).

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
        classes = {"LaneKeep": LaneKeepEnv, "ACC": ACCEnv, "Track": TrackEnv}
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
        self._views: Dict[str, np.ndarray] = {}
        column = 0
        for key, space in self.single_observation_space.spaces.items():
            width = int(np.prod(space.shape))
            self._views[key] = self._obs[:, column : column + width].reshape(n, *space.shape)
            column += width
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
