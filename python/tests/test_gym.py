"""The gymnasium environments: gymnasium's own checker on every id, identical trajectories
for the same seed, finite observations over 10⁴ random steps, the default rewards' formulas,
replaceable rewards, observations the caller keeps, bad actions refused, render."""

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")
from gymnasium.utils.env_checker import check_env  # noqa: E402

import webots_vehicle.gym as wvgym  # noqa: E402  (registers the ids)

IDS = ["WebotsVehicle/LaneKeep-v0", "WebotsVehicle/ACC-v0", "WebotsVehicle/Track-v0"]


@pytest.mark.parametrize("env_id", IDS)
def test_check_env(env_id):
    env = gymnasium.make(env_id, render_mode="rgb_array")
    check_env(env.unwrapped, skip_render_check=False)
    env.close()


def _trajectory(env, seed, actions):
    obs, _ = env.reset(seed=seed)
    out = [obs]
    for a in actions:
        obs, reward, terminated, truncated, _ = env.step(a)
        out.append(dict(obs, reward=np.float32(reward)))
        if terminated or truncated:
            break
    return out


@pytest.mark.parametrize("env_id", IDS)
def test_same_seed_same_trajectory(env_id):
    env = gymnasium.make(env_id)
    actions = np.random.default_rng(1).uniform(-1, 1, size=(60, 2)).astype(np.float32)
    first = _trajectory(env, 7, actions)
    second = _trajectory(env, 7, actions)
    assert len(first) == len(second)
    for a, b in zip(first, second):
        assert a.keys() == b.keys()
        for k in a:
            assert np.array_equal(a[k], b[k]), k
    # Another seed draws another start (ACC: another lead speed, seen by the radar).
    other = _trajectory(env, 8, actions)
    key = "radar" if env_id.endswith("ACC-v0") else "car"
    assert not all(np.array_equal(a[key], b[key]) for a, b in zip(first, other))


def test_random_policy_runs_ten_thousand_steps_with_finite_observations():
    env = gymnasium.make("WebotsVehicle/LaneKeep-v0")
    env.action_space.seed(3)
    obs, _ = env.reset(seed=3)
    for _ in range(10_000):
        obs, reward, terminated, truncated, _ = env.step(env.action_space.sample())
        assert all(np.all(np.isfinite(v)) for v in obs.values())
        assert np.isfinite(reward)
        if terminated or truncated:
            obs, _ = env.reset()


def test_options_place_the_car_and_rewards_are_replaceable():
    env = gymnasium.make(
        "WebotsVehicle/Track-v0", reward_fn=lambda env, obs, action: float(obs["car"][0])
    )
    obs, _ = env.reset(seed=0, options={"pose": (0.0, 0.0, 0.0), "speed": 12.0})
    assert obs["car"][0] == pytest.approx(12.0, abs=0.3)
    assert obs["track"][0] == pytest.approx(0.0, abs=0.05)
    _, reward, *_ = env.step(np.zeros(2, dtype=np.float32))
    assert reward == pytest.approx(12.0, abs=0.5)


def _obs(car, **extra):
    return {"car": np.array(car, dtype=np.float32), **{k: np.asarray(v, dtype=np.float32) for k, v in extra.items()}}


def test_default_rewards_follow_their_documented_formulas():
    # The formulas of the functions' docstrings, by hand. 0.5, 12, 15, 30 and 3.75 are exact in
    # float32, so the only rounding is the float64 arithmetic's: 1e-12.
    lane = wvgym.LaneKeepEnv()
    on_road = _obs([15, 0, 0, 0, 15], lane=[0.5, 0, 0, 0, 3.75, 1])
    # 15/30 − 0.5² − 0.1 × 1² (heading error 0: the whole speed is along the lane).
    assert wvgym.lane_keep_reward(lane, on_road, np.array([1.0, 0.0])) == pytest.approx(0.15, abs=1e-12)
    # The speed term saturates at 30 m/s; an action beyond 1 counts as 1.
    fast = _obs([45, 0, 0, 0, 45], lane=[0, 0, 0, 0, 3.75, 1])
    assert wvgym.lane_keep_reward(lane, fast, np.array([2.0, 0.0])) == pytest.approx(0.9, abs=1e-12)
    off_road = _obs([15, 0, 0, 0, 15], lane=[0, 0, 0, 0, 0, 0])
    assert wvgym.lane_keep_reward(lane, off_road, np.zeros(2)) == -10.0
    track = wvgym.TrackEnv()
    # 1 − 0.5 − |12 − 10| / 10.
    assert wvgym.track_reward(track, _obs([12, 0, 0, 0, 12], track=[0.5, 0]), np.zeros(2)) == pytest.approx(0.3, abs=1e-12)
    acc = wvgym.ACCEnv()
    acc.reset(seed=0)  # 50 m apart: not touching
    radar, mask = np.zeros((8, 4)), np.zeros(8)
    radar[0], mask[0] = (30.0, 0.0, 0.0, -40.0), 1.0
    # A 30 m gap at 12 m/s is 2.5 s: −(2.5 − 2)² − 0.1 × 0.5².
    seen = _obs([12, 0, 0, 0, 12], radar=radar, radar_mask=mask)
    assert wvgym.acc_reward(acc, seen, np.array([0.0, 0.5])) == pytest.approx(-0.275, abs=1e-12)
    assert wvgym.acc_reward(acc, _obs([12, 0, 0, 0, 12], radar=np.zeros((8, 4)), radar_mask=np.zeros(8)), np.zeros(2)) == -1.0


@pytest.mark.parametrize("cls", [wvgym.LaneKeepEnv, wvgym.ACCEnv, wvgym.TrackEnv])
def test_the_reward_returned_is_the_default_function_of_the_observation(cls):
    env = cls()
    env.reset(seed=2)
    actions = np.random.default_rng(2).uniform(-1.2, 1.2, size=(30, 2)).astype(np.float32)
    for a in actions:
        obs, reward, terminated, truncated, info = env.step(a)
        # The same Rust formula on the float32 observation returned: equal to the last bit.
        assert reward == env.default_reward_fn(env, obs, np.clip(a.astype(np.float64), -1, 1))
        assert info["time"] == env.sim.time
        if terminated or truncated:
            break


def test_observations_are_the_callers_to_keep():
    env = wvgym.TrackEnv()
    first, _ = env.reset(seed=1)
    kept = {k: v.copy() for k, v in first.items()}
    second, *_ = env.step(np.zeros(2, dtype=np.float32))
    for key in kept:
        np.testing.assert_array_equal(first[key], kept[key])
    assert not np.array_equal(first["car"], second["car"])


def test_copy_false_returns_the_arrays_the_next_step_overwrites():
    copies, views = wvgym.TrackEnv(), wvgym.TrackEnv(copy=False)
    first, _ = copies.reset(seed=1)
    view, _ = views.reset(seed=1)
    for key in first:
        np.testing.assert_array_equal(view[key], first[key])
    second, *_ = copies.step(np.zeros(2, dtype=np.float32))
    again, *_ = views.step(np.zeros(2, dtype=np.float32))
    # The same arrays, now holding the second observation.
    assert again["car"] is view["car"]
    np.testing.assert_array_equal(view["car"], second["car"])


def test_a_replacement_reward_gets_the_clipped_action():
    seen = []
    env = wvgym.LaneKeepEnv(reward_fn=lambda env, obs, a: seen.append(a) or 2.5)
    env.reset(seed=0)
    _, reward, *_ = env.step(np.array([3.0, -0.5], dtype=np.float32))
    assert reward == 2.5
    assert seen[0].dtype == np.float64 and list(seen[0]) == [1.0, -0.5]


def test_bad_actions_are_refused():
    env = wvgym.LaneKeepEnv()
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"action\[1\] must be finite, not NaN"):
        env.step(np.array([0.0, np.nan], dtype=np.float32))
    with pytest.raises(ValueError, match="2 values"):
        env.step(np.zeros(3))
    with pytest.raises(TypeError):
        env.step("left")
    # A list, or float64, is as good as the space's float32.
    env.step([0.1, 0.0])
    env.step(np.array([0.1, 0.0]))


def test_render_shows_the_car():
    env = gymnasium.make("WebotsVehicle/ACC-v0", render_mode="rgb_array")
    env.reset(seed=0)
    image = env.render()
    assert image.shape == (128, 128, 3) and image.dtype == np.uint8
    red = (image[..., 0] > 200) & (image[..., 1] < 60)
    assert red.sum() > 20  # the follower, about 9.6 × 3.8 pixels
    assert red[64, 64 + 2]  # 1 m ahead of its origin, at the centre row


@pytest.mark.parametrize(
    "action",
    [
        np.array([0.3, -0.2], dtype=np.float32),
        np.array([0.3, -0.2], dtype=np.float64),
        np.array([[0.3, -0.2]], dtype=np.float32),
        [0.3, -0.2],
        (0.3, -0.2),
    ],
    ids=["float32", "float64", "float32 (1, 2)", "list", "tuple"],
)
def test_every_form_of_an_action_drives_the_same_step(action):
    # The native step reads a 1-D numpy array directly and anything else through the buffer
    # protocol or as a sequence: the same two numbers give the same step. The float32 value
    # of 0.3 is not the float64 one, so each is compared with its own reference.
    wide = np.float32 if getattr(action, "dtype", None) == np.float32 else np.float64
    reference, env = wvgym.TrackEnv(), wvgym.TrackEnv()
    reference.reset(seed=3)
    env.reset(seed=3)
    expected = reference.step(np.array([0.3, -0.2], dtype=wide).astype(np.float64))
    got = env.step(action)
    for key in expected[0]:
        np.testing.assert_array_equal(got[0][key], expected[0][key])
    assert got[1:] == expected[1:]


@pytest.mark.parametrize("action", [np.zeros(3, dtype=np.float32), np.zeros(1), [0.0, 0.0, 0.0]])
def test_an_action_of_the_wrong_length_is_refused_with_its_length(action):
    env = wvgym.TrackEnv()
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"2 values \(steering, acceleration\), not [13]"):
        env.step(action)


def test_a_step_returns_gymnasiums_five_tuple_of_fresh_objects():
    env = wvgym.ACCEnv()
    env.reset(seed=4)
    a = env.step(np.zeros(2, dtype=np.float32))
    b = env.step(np.zeros(2, dtype=np.float32))
    assert isinstance(a, tuple) and len(a) == 5
    assert list(a[0]) == list(env.observation_space.spaces)
    assert a[0]["radar"].shape == (wvgym.RADAR_TARGETS, 4) and a[0]["radar"].dtype == np.float32
    assert a[0]["car"] is not b[0]["car"] and a[4] is not b[4]
    assert env.observation_space.contains(a[0])
    assert a[4]["time"] < b[4]["time"] and b[4] == {"time": env.sim.time}


def test_a_reward_set_after_construction_is_used_and_can_be_removed():
    env, reference = wvgym.TrackEnv(), wvgym.TrackEnv()
    env.reset(seed=5)
    reference.reset(seed=5)
    env.reward_fn = lambda e, obs, a: 42.0
    assert env.step(np.zeros(2, dtype=np.float32))[1] == 42.0
    env.reward_fn = None
    a = np.full(2, 0.5, dtype=np.float32)
    reference.step(np.zeros(2, dtype=np.float32))
    assert env.step(a)[1] == reference.step(a)[1]


def test_a_subclass_overriding_step_gets_its_own_step():
    class Counting(wvgym.TrackEnv):
        calls = 0

        def step(self, action):
            Counting.calls += 1
            return super().step(action)

    env = Counting()
    env.reset(seed=0)
    env.step(np.zeros(2, dtype=np.float32))
    assert Counting.calls == 1
