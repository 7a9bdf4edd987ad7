"""The four samplers: each one's defining property, validity, determinism, bad input."""

import numpy as np
import pytest

from toolkit import scenarios
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.planning.local_planner import segment_points
from toolkit.planning.sampling import SAMPLERS, Sampler, make_sampler


def setting(name: str, index: int = 0):
    scenario = scenarios.get(name)
    ws = scenario.workspaces("query", index + 1, seed=0)[index]
    return scenario.robot, exact_checker(ws, scenario.robot)


@pytest.mark.parametrize("scenario", ["2ds", "3dc9"])
@pytest.mark.parametrize("name", sorted(SAMPLERS))
def test_samples_are_valid_in_bounds_and_deterministic(scenario, name):
    robot, checker = setting(scenario)
    sampler = make_sampler(name, checker)
    Q = sampler.sample(300, np.random.default_rng(3))
    assert Q.ndim == 2 and Q.shape[1] == robot.dof and 0 < len(Q) <= 300
    assert checker.are_valid(Q).all()
    assert robot.in_bounds(Q).all()
    np.testing.assert_array_equal(Q, sampler.sample(300, np.random.default_rng(3)))


def test_uniform_keeps_exactly_the_valid_draws():
    robot, checker = setting("2ds")
    Q = make_sampler("BS", checker).sample(500, np.random.default_rng(1))
    draws = robot.sample(np.random.default_rng(1), 500)
    np.testing.assert_array_equal(Q, draws[checker.are_valid(draws)])


def _perturbed_invalid_fraction(robot, checker, Q, scale, rng):
    """Fraction of ``Q``'s small random perturbations (8 each) that are invalid."""
    Q = np.repeat(Q, 8, axis=0)
    moved = robot.wrap(Q + rng.normal(0.0, scale, size=Q.shape))
    return 1.0 - checker.are_valid(moved).mean()


@pytest.mark.parametrize("scenario", ["2ds", "3dc7", "3dc9"])
def test_obstacle_based_samples_lie_near_the_boundary(scenario, rng):
    robot, checker = setting(scenario)
    ob = make_sampler("OB", checker)
    near = ob.sample(400, rng)
    uniform = make_sampler("BS", checker).sample(400, rng)
    scale = ob.resolution / 4  # a quarter of a walking step, per DoF
    ob_fraction = _perturbed_invalid_fraction(robot, checker, near, scale, rng)
    bs_fraction = _perturbed_invalid_fraction(robot, checker, uniform, scale, rng)
    assert ob_fraction > 0.1
    assert ob_fraction > 3 * bs_fraction


def test_obstacle_based_bisection_brings_samples_closer():
    robot, checker = setting("2ds")
    coarse = make_sampler("OB", checker).sample(400, np.random.default_rng(0))
    tight = make_sampler("OB", checker, bisections=6).sample(400, np.random.default_rng(0))
    rng = np.random.default_rng(1)
    step = 0.02
    assert _perturbed_invalid_fraction(robot, checker, tight, step, rng) > 2 * _perturbed_invalid_fraction(
        robot, checker, coarse, step, rng
    )


def _pairs(sampler, n, seed):
    """The (q1, q2) pairs that G and BT draw for ``n`` attempts (same draws, same order)."""
    rng = np.random.default_rng(seed)
    Q1 = sampler.robot.sample(rng, n)
    return Q1, sampler.near(Q1, rng)


@pytest.mark.parametrize("scenario", ["2ds", "3dc7"])
def test_gaussian_keeps_the_valid_one_of_a_mixed_pair(scenario):
    robot, checker = setting(scenario)
    sampler = make_sampler("G", checker)
    Q = sampler.sample(400, np.random.default_rng(5))
    Q1, Q2 = _pairs(sampler, 400, 5)
    v1, v2 = sampler.valid(Q1), sampler.valid(Q2)
    for q in Q:
        i = np.flatnonzero(np.all(q == Q1, axis=1) | np.all(q == Q2, axis=1))
        assert len(i) == 1 and v1[i[0]] != v2[i[0]]  # its Gaussian partner is invalid
    assert len(Q) == np.sum(v1 != v2)
    # the partner lies at Gaussian distance sigma = 0.1 x the bounds' diagonal per axis
    np.testing.assert_allclose(sampler.sigma, 0.1 * np.linalg.norm(robot.upper - robot.lower))


@pytest.mark.parametrize("scenario", ["2ds", "3dc7"])
def test_bridge_midpoints_are_valid_between_invalid_ends(scenario):
    robot, checker = setting(scenario)
    sampler = make_sampler("BT", checker)
    Q = sampler.sample(2000, np.random.default_rng(2))
    Q1, Q2 = _pairs(sampler, 2000, 2)
    both_invalid = ~sampler.valid(Q1) & ~sampler.valid(Q2)
    middles = segment_points(robot, Q1, Q2, np.full(len(Q1), 0.5))
    expected = middles[both_invalid & sampler.valid(middles)]
    assert len(Q) > 0
    np.testing.assert_allclose(Q, expected)
    assert not checker.are_valid(Q1[both_invalid]).any()


class CallCounter(CollisionChecker):
    """The exact answers, counting calls; ``few_calls`` as given."""

    def __init__(self, exact: CollisionChecker, few_calls: bool):
        super().__init__(exact.robot)
        self.exact, self.few_calls, self.calls = exact, few_calls, 0

    def validity(self, Q):
        self.calls += 1
        return self.exact.validity(Q)


def test_a_few_calls_checker_gets_the_same_bridge_samples_in_one_call():
    _, exact = setting("3dc7")
    many, few = CallCounter(exact, few_calls=False), CallCounter(exact, few_calls=True)
    Q = make_sampler("BT", many).sample(300, np.random.default_rng(5))
    np.testing.assert_array_equal(make_sampler("BT", few).sample(300, np.random.default_rng(5)), Q)
    assert len(Q) > 0 and (many.calls, few.calls) == (3, 1)


def test_gaussian_neighbours_wrap_angles():
    robot, checker = setting("3dc7")
    sampler = make_sampler("G", checker, sigma=5.0)
    near = sampler.near(np.zeros((1000, robot.dof)), np.random.default_rng(0))
    angles = near[:, robot.wraps]
    assert angles.min() >= -np.pi and angles.max() < np.pi and np.abs(angles).max() > 3.0


def test_bad_input_gives_clear_errors():
    _, checker = setting("2ds")
    with pytest.raises(ValueError, match="unknown sampler 'XX'"):
        make_sampler("XX", checker)
    with pytest.raises(ValueError, match="bad options"):
        make_sampler("BS", checker, sigma=1.0)
    with pytest.raises(ValueError, match="sigma must be positive"):
        make_sampler("G", checker, sigma=-1.0)
    with pytest.raises(ValueError, match="n_attempts"):
        make_sampler("BS", checker).sample(-3, np.random.default_rng(0))


def test_valid_calls_out_of_bounds_invalid_and_asks_the_checker_about_the_rest_in_one_call():
    _, exact = setting("2ds")
    counting = CallCounter(exact, few_calls=False)
    sampler = make_sampler("BS", counting)
    inside = np.array([[5.0, 5.0], [30.0, 30.0]])
    outside = np.array([[-1.0, 5.0], [5.0, 40.0]])
    Q = np.concatenate([inside, outside])  # (4, 2)
    np.testing.assert_array_equal(sampler.valid(Q), np.concatenate([exact.are_valid(inside), [False, False]]))
    assert counting.calls == 1


def test_a_sampler_subclass_overrides_draw_and_sample_calls_it():
    class EveryOther(Sampler):
        def draw(self, n, rng):
            Q = self.robot.sample(rng, n)  # (n, dof)
            return Q[::2][self.valid(Q[::2])]

    robot, checker = setting("2ds")
    Q = EveryOther(checker).sample(100, np.random.default_rng(2))
    draws = robot.sample(np.random.default_rng(2), 100)[::2]
    np.testing.assert_array_equal(Q, draws[checker.are_valid(draws)])
    with pytest.raises(NotImplementedError, match="must override draw"):
        Sampler(checker).sample(10, np.random.default_rng(0))
