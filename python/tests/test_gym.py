"""The gymnasium environments: gymnasium's own checker on every id, identical trajectories
for the same seed, finite observations over 10⁴ random steps, replaceable rewards, render."""

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


def test_render_shows_the_car():
    env = gymnasium.make("WebotsVehicle/ACC-v0", render_mode="rgb_array")
    env.reset(seed=0)
    image = env.render()
    assert image.shape == (128, 128, 3) and image.dtype == np.uint8
    red = (image[..., 0] > 200) & (image[..., 1] < 60)
    assert red.sum() > 20  # the follower, about 9.6 × 3.8 pixels
    assert red[64, 64 + 2]  # 1 m ahead of its origin, at the centre row
