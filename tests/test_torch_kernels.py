"""The exact check in torch (issue 50, item 2) gives the compiled kernel's and FCL's answers, run on the CPU.

The same code runs on a GPU (torch_kernels' docstring); here it runs on the CPU, so CI holds
that code path to the references: uniform configurations, pairs within 1e-6 of contact on
either side (obstacles and region walls), configurations on the bounds, exact contacts,
a 2D arm and boxes of any size. Then the interface: a tensor is answered in kind, on its
device; float32 tensors are widened without loss; bad tensors are named.
"""

import numpy as np
import pytest
import torch
from hypothesis import given, settings
from test_compiled_checker import (
    DYADIC_2D,
    DYADIC_3D,
    planar_arm,
    scattered_boxes,
    seeds,
    straddle_the_boundary,
)

from toolkit import scenarios
from toolkit.geometry.collision import CompiledChecker, FCLChecker
from toolkit.geometry.torch_kernels import TorchChecker
from toolkit.geometry.workspace import Workspace

SCENARIOS = ["2ds", "3do", "3dc7", "3dc9"]


def assert_agrees(ws, robot, Q) -> np.ndarray:
    """The torch checker's answers on ``Q``, asserted equal to the compiled kernel's and FCL's."""
    answer = TorchChecker(ws, robot).are_valid(Q)
    np.testing.assert_array_equal(answer, CompiledChecker(ws, robot).are_valid(Q), err_msg="torch vs compiled")
    np.testing.assert_array_equal(answer, FCLChecker(ws, robot).are_valid(Q), err_msg="torch vs FCL")
    return answer


@pytest.mark.parametrize("name", SCENARIOS)
def test_uniform_and_near_contact_configurations(name):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(20)
    ws = scenario.make_workspace(rng)
    uniform = robot.sample(rng, 5000)
    inside, outside = straddle_the_boundary(CompiledChecker(ws, robot), rng, 500)
    assert len(inside) > 250
    valid = assert_agrees(ws, robot, np.concatenate([uniform, inside, outside]))
    assert 0.05 < valid[: len(uniform)].mean() < 0.95
    assert valid[len(uniform) : len(uniform) + len(inside)].all() and not valid[-len(outside) :].any()


@pytest.mark.parametrize("name", ["3do", "3dc9"])
def test_on_the_bounds_and_a_step_beyond(name):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(21)
    ws = scenario.make_workspace(rng)
    Q = robot.sample(rng, 200)
    dof = rng.integers(robot.dof, size=len(Q))
    Q[np.arange(len(Q)), dof] = robot.upper[dof]
    beyond = Q.copy()
    beyond[np.arange(len(Q)), dof] = np.nextafter(robot.upper[dof], np.inf)
    assert assert_agrees(ws, robot, Q).any()
    assert not assert_agrees(ws, robot, beyond).any()


@pytest.mark.parametrize("robot", [DYADIC_3D, DYADIC_2D], ids=["3d", "2d"])
@pytest.mark.parametrize("gap", [0.0, 2.0**-20, -(2.0**-20)])
def test_a_face_touching_exactly_is_a_collision(robot, gap):
    """A box against the second link's +x face: touching collides; 2^-20 away it does not; into it, it does."""
    dim = robot.dim
    q = np.zeros(robot.dof)
    q[:dim] = 3.0
    lo, hi = robot.link_aabbs(q)[0][1]  # (D,) each: the second link, unturned
    box = np.stack([lo - 0.25, hi + 0.25])
    box[:, 0] = hi[0] + gap, hi[0] + gap + 1.0
    ws = Workspace(np.zeros(dim), np.full(dim, 8.0), box[None])
    assert assert_agrees(ws, robot, q[None])[0] == (gap > 0)


@settings(max_examples=4, deadline=None)
@given(seed=seeds)
def test_a_2d_arm_and_boxes_of_any_size(seed):
    rng = np.random.default_rng(seed)
    arm = planar_arm()
    ws = Workspace(np.zeros(2), np.full(2, 31.0), scattered_boxes(rng, np.zeros(2), np.full(2, 31.0), 12))
    inside, outside = straddle_the_boundary(CompiledChecker(ws, arm), rng, 100)
    assert_agrees(ws, arm, np.concatenate([arm.sample(rng, 1000), inside, outside]))
    robot, lower, upper = scenarios.get("3dc9").robot, np.zeros(3), np.full(3, 11.0)
    ws = Workspace(lower, upper, scattered_boxes(rng, lower, upper, 40))
    inside, outside = straddle_the_boundary(CompiledChecker(ws, robot), rng, 100)
    assert_agrees(ws, robot, np.concatenate([robot.sample(rng, 1000), inside, outside]))


def test_a_tensor_is_answered_in_kind_and_a_float32_one_exactly():
    scenario = scenarios.get("3dc7")
    robot, rng = scenario.robot, np.random.default_rng(22)
    ws = scenario.make_workspace(rng)
    Q = robot.sample(rng, 3000).astype(np.float32)  # (N, dof): the numbers a float32 batch holds
    checker = TorchChecker(ws, robot)
    answer = checker.are_valid(torch.from_numpy(Q))
    assert answer.dtype == torch.bool and answer.shape == (len(Q),) and answer.device.type == "cpu"
    np.testing.assert_array_equal(answer.numpy(), CompiledChecker(ws, robot).are_valid(Q.astype(np.float64)))
    assert checker.n_checked == len(Q)
    one = checker.are_valid(torch.from_numpy(Q[0]))  # a single configuration: one answer
    assert one.shape == (1,) and bool(one[0]) == bool(answer[0])


def test_any_checker_answers_a_tensor_in_kind_through_the_host():
    """A checker that computes on the host (FCL here) takes a tensor too, and answers with one."""
    scenario = scenarios.get("3dc7")
    robot, rng = scenario.robot, np.random.default_rng(23)
    ws = scenario.make_workspace(rng)
    Q = robot.sample(rng, 500)
    answer = FCLChecker(ws, robot).are_valid(torch.from_numpy(Q))
    assert isinstance(answer, torch.Tensor)
    np.testing.assert_array_equal(answer.numpy(), CompiledChecker(ws, robot).are_valid(Q))


def test_non_finite_rows_of_a_tensor_are_invalid_and_bad_tensors_are_named():
    scenario = scenarios.get("3dc7")
    robot = scenario.robot
    ws = scenario.make_workspace(np.random.default_rng(24))
    checker = TorchChecker(ws, robot)
    Q = torch.from_numpy(robot.sample(np.random.default_rng(0), 3))
    Q[0, 0], Q[1, 4] = float("nan"), float("inf")
    assert checker.are_valid(Q)[:2].tolist() == [False, False]
    with pytest.raises(ValueError, match=r"shape \(N, 7\)"):
        checker.are_valid(torch.zeros(3, 6))
    with pytest.raises(ValueError, match="floating-point"):
        checker.are_valid(torch.zeros(3, 7, dtype=torch.int64))
    with pytest.raises(ValueError, match="NaN"):
        checker.are_valid(Q.numpy())  # a numpy batch keeps its error


def test_chunks_give_the_answers_of_one_call(monkeypatch):
    scenario = scenarios.get("3dc9")
    robot, rng = scenario.robot, np.random.default_rng(25)
    ws = scenario.make_workspace(rng)
    Q = robot.sample(rng, 2000)
    whole = TorchChecker(ws, robot).are_valid(Q)
    monkeypatch.setattr(TorchChecker, "CHUNK", 300)
    chunked = TorchChecker(ws, robot)
    np.testing.assert_array_equal(chunked.are_valid(Q), whole)
    np.testing.assert_array_equal(chunked.are_valid(torch.from_numpy(Q)).numpy(), whole)
