"""webots_vehicle.gym.VectorEnv: each of its copies equals a single environment given the
same seed and actions, bit for bit (observations, rewards, flags), including across a
NEXT_STEP autoreset; gymnasium's make_vec builds it; its batches lie in its spaces; bad
actions are refused."""

from pathlib import Path

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

import webots_vehicle.gym as wvgym  # noqa: E402  (registers the ids)

TASKS = [("LaneKeep", wvgym.LaneKeepEnv), ("ACC", wvgym.ACCEnv), ("Track", wvgym.TrackEnv)]


def _assert_same(vec_obs, i, single_obs):
    for key, value in single_obs.items():
        # Bit for bit: both run sim::vec_env::TaskEnv from the same start and actions (this
        # checks the starts drawn per seed, the action and observation plumbing, and the
        # autoreset), so no tolerance is needed.
        np.testing.assert_array_equal(vec_obs[key][i], value, err_msg=key)


@pytest.mark.parametrize("task,cls", TASKS)
def test_copies_equal_single_environments_bit_for_bit(task, cls):
    n, steps, seed = 3, 40, 11
    actions = np.random.default_rng(5).uniform(-1, 1, size=(steps, n, 2)).astype(np.float32)
    vec = wvgym.VectorEnv(task, num_envs=n)
    obs, _ = vec.reset(seed=seed)
    singles = [cls() for _ in range(n)]
    for i, env in enumerate(singles):
        single_obs, _ = env.reset(seed=seed + i)
        _assert_same(obs, i, single_obs)
    for t in range(steps):
        obs, rewards, terminated, truncated, _ = vec.step(actions[t])
        for i, env in enumerate(singles):
            single_obs, reward, term, trunc, _ = env.step(actions[t, i])
            _assert_same(obs, i, single_obs)
            assert rewards[i] == reward
            assert (terminated[i], truncated[i]) == (term, trunc)
        if terminated.any() or truncated.any():
            break


def test_autoreset_is_next_step_and_matches_a_single_reset():
    # Full right steering leaves the lane within a few seconds: the episode terminates.
    vec = wvgym.VectorEnv("LaneKeep", num_envs=2)
    assert vec.metadata["autoreset_mode"] == gymnasium.vector.AutoresetMode.NEXT_STEP
    single = wvgym.LaneKeepEnv()
    vec.reset(seed=3)
    single.reset(seed=3)
    action = np.array([[1.0, 1.0], [0.0, 0.0]])
    for _ in range(400):
        obs, rewards, terminated, truncated, _ = vec.step(action)
        single_obs, reward, term, _, _ = single.step(action[0])
        assert rewards[0] == reward
        if terminated[0]:
            break
    assert terminated[0] and term and not terminated[1]
    # The next step resets copy 0 (its action ignored) and steps copy 1.
    obs, rewards, terminated, truncated, _ = vec.step(action)
    single_obs, _ = single.reset()  # its generator goes on, as the copy's does
    _assert_same(obs, 0, single_obs)
    assert rewards[0] == 0.0 and not terminated[0] and not truncated[0]
    # And it runs on as a fresh episode.
    obs, rewards, _, _, _ = vec.step(action)
    single_obs, reward, _, _, _ = single.step(action[0])
    _assert_same(obs, 0, single_obs)
    assert rewards[0] == reward


@pytest.mark.parametrize("env_id", ["WebotsVehicle/LaneKeep-v0", "WebotsVehicle/ACC-v0"])
def test_make_vec_builds_it_and_batches_lie_in_the_spaces(env_id):
    envs = gymnasium.make_vec(env_id, num_envs=4, vectorization_mode="vector_entry_point")
    assert isinstance(envs.unwrapped, wvgym.VectorEnv) and envs.num_envs == 4
    assert envs.single_observation_space == gymnasium.make(env_id).observation_space
    obs, _ = envs.reset(seed=0)
    assert obs in envs.observation_space
    envs.action_space.seed(0)
    for _ in range(50):
        obs, rewards, terminated, truncated, _ = envs.step(envs.action_space.sample())
        assert obs in envs.observation_space
        assert rewards.shape == (4,) and rewards.dtype == np.float64
        assert np.all(np.isfinite(rewards))
        assert terminated.dtype == np.bool_ and truncated.dtype == np.bool_
    envs.close()


def test_copy_false_returns_views_the_next_step_overwrites():
    vec = wvgym.VectorEnv("Track", num_envs=2, copy=False)
    first, _ = vec.reset(seed=1)
    kept = first["car"].copy()
    vec.step(np.zeros((2, 2)))
    assert not np.array_equal(first["car"], kept)


def test_bad_arguments_are_refused():
    vec = wvgym.VectorEnv("LaneKeep", num_envs=2)
    vec.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions\[1\]\[0\] must be finite, not NaN"):
        vec.step(np.array([[0.0, 0.0], [np.nan, 0.0]]))
    with pytest.raises(ValueError, match="shape"):
        vec.step(np.zeros((3, 2)))
    with pytest.raises(ValueError, match="task"):
        wvgym.VectorEnv("Drift", num_envs=2)
    with pytest.raises(ValueError, match="num_envs"):
        wvgym.VectorEnv("ACC", num_envs=0)


def test_the_readme_training_loop_runs():
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
    section = readme.split("### The vector environment", 1)[1]
    code = section.split("```python\n", 1)[1].split("```", 1)[0]
    assert len(code.strip().splitlines()) <= 15
    scope: dict = {}
    exec(compile(code, "python/README.md", "exec"), scope)
    # 3 generations of 8 policies, 100 steps each: a best policy was kept.
    assert scope["best"].shape == (2, 11) and np.isfinite(scope["best_return"])
