"""Extension points (issue 19): a sampler of your own by name, a robot of your own as a registered scenario."""

import dataclasses
import json
import sys
from pathlib import Path

import numpy as np
import pytest

from toolkit import cli, scenarios
from toolkit.geometry import robots
from toolkit.geometry.collision import (
    CompiledChecker,
    FCLChecker,
    PointRobotChecker,
    SeparatingAxisChecker,
    exact_checker,
)
from toolkit.geometry.robots import BoxRobot, Joint, Link
from toolkit.geometry.workspace import Workspace
from toolkit.learning import checkpoints, encoding, presets
from toolkit.learning.learned import LearnedChecker
from toolkit.learning.training import TrainedModels
from toolkit.planning import sampling
from toolkit.planning.local_planner import default_resolution, path_is_valid
from toolkit.planning.paper_prm import PRM
from toolkit.planning.planner import REFINEMENT
from toolkit.planning.prm import plan
from toolkit.util import plugins


@pytest.fixture(autouse=True)
def fresh_registries(monkeypatch):
    """Registrations made by a test end with it."""
    monkeypatch.setattr(sampling, "SAMPLERS", dict(sampling.SAMPLERS))
    monkeypatch.setattr(scenarios, "SCENARIOS", dict(scenarios.SCENARIOS))


class CornerSampler(sampling.Sampler):
    """Test sampler: uniform samples, kept only in the lower-left quarter of the bounds."""

    def draw(self, n, rng):
        Q = self.robot.sample(rng, n)
        Q = Q[np.all((self.robot.lower + self.robot.upper) / 2 > Q, axis=1)]
        return Q[self.valid(Q)]


def planar_arm() -> BoxRobot:
    """A 3-link arm on a sliding 2D base: 5 DoF."""
    links = [
        Link((0.4, 0.4, 0.0)),
        Link((1.0, 0.15, 0.0), (1.0, 0.0, 0.0)),
        Link((0.75, 0.15, 0.0), (0.75, 0.0, 0.0)),
        Link((0.5, 0.15, 0.0), (0.5, 0.0, 0.0)),
    ]
    joints = [
        Joint((0.0, 0.0, 0.0), "z", (-3.0, 3.0)),
        Joint((2.0, 0.0, 0.0), "z", (-2.6, 2.6)),
        Joint((1.5, 0.0, 0.0), "z", (-2.6, 2.6)),
    ]
    return BoxRobot("arm2d", "point2d", links, joints, position_bounds=(np.full(2, 0.4), np.full(2, 30.6)))


def arm_scenario() -> scenarios.Scenario:
    return dataclasses.replace(
        scenarios.get("2ds"), name="2ds-arm", title="2D simple, planar 3-link arm", robot=planar_arm()
    )


# -- samplers -----------------------------------------------------------------------------


def test_a_registered_sampler_is_built_by_name_and_plans():
    sampling.register_sampler("CORNER", CornerSampler)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[20.0, 20.0], [25.0, 25.0]]]))
    exact = exact_checker(ws, robots.point_robot())
    sampler = sampling.make_sampler("CORNER", exact)
    assert type(sampler) is CornerSampler
    samples = sampler.sample(400, np.random.default_rng(0))
    assert 0 < len(samples) < 400 and np.all(samples < 15.5)
    result = plan(
        exact,
        np.array([2.0, 2.0]),
        np.array([12.0, 12.0]),
        sampler="CORNER",
        planner=PRM(n_samples=200),
        rng=np.random.default_rng(0),
    )
    assert result.success and np.all(result.path < 15.5)


def test_register_sampler_refuses_taken_names_and_non_samplers():
    with pytest.raises(ValueError, match="replace=True"):
        sampling.register_sampler("OB", CornerSampler)
    assert sampling.register_sampler("OB", CornerSampler, replace=True) is CornerSampler
    assert sampling.SAMPLERS["OB"] is CornerSampler
    with pytest.raises(TypeError, match="Sampler"):
        sampling.register_sampler("X", object)
    with pytest.raises(ValueError, match="name"):
        sampling.register_sampler("", CornerSampler)
    with pytest.raises(ValueError, match="unknown sampler"):
        sampling.make_sampler(
            "NOPE",
            exact_checker(Workspace(np.zeros(2), np.ones(2), np.zeros((0, 2, 2))), robots.point_robot((1.0, 1.0))),
        )


# -- robots -------------------------------------------------------------------------------


def test_position_dofs_come_first_for_every_base():
    assert [r.n_positions for r in (robots.point_robot(), robots.youbot(), robots.box_chain(1), planar_arm())] == [
        2,
        2,
        3,
        2,
    ]
    assert encoding.InputEncoding(planar_arm(), (41, 41, 6), 0, "raw").n_pos == 2  # not 5: joints are no positions


def test_a_2d_arm_is_checked_compiled_and_agrees_with_fcl_and_separating_axes():
    arm = planar_arm()
    ws = scenarios.get("2ds").make_workspace(np.random.default_rng(0))
    checker = exact_checker(ws, arm)
    assert type(checker) is CompiledChecker  # the numpy shortcut is for the lone square only
    assert type(exact_checker(ws, robots.point_robot())) is PointRobotChecker
    Q = arm.sample(np.random.default_rng(1), 3000)
    valid = checker.are_valid(Q)
    assert 0.2 < valid.mean() < 0.9
    np.testing.assert_array_equal(valid, SeparatingAxisChecker(ws, arm).are_valid(Q))
    np.testing.assert_array_equal(valid, FCLChecker(ws, arm).are_valid(Q))


def test_a_2d_robots_joints_must_turn_in_the_plane_and_have_limits():
    with pytest.raises(ValueError, match="about z"):
        BoxRobot(
            "bad",
            "point2d",
            [Link((0.5, 0.5, 0.0)), Link((0.5, 0.1, 0.0))],
            [Joint((0, 0, 0), "y", (-1, 1))],
            position_bounds=(np.zeros(2), np.ones(2)),
        )
    with pytest.raises(ValueError, match="lower < upper"):
        BoxRobot(
            "bad",
            "free",
            [Link((0.5, 0.5, 0.5)), Link((0.5, 0.1, 0.1))],
            [Joint((0, 0, 0), "z", (1, -1))],
            position_bounds=(np.zeros(3), np.ones(3)),
        )


# -- scenarios ----------------------------------------------------------------------------


def test_a_registered_scenario_is_found_by_name_and_its_checkpoints_load(tmp_path):
    scenario = scenarios.register(arm_scenario())
    assert scenarios.get("2ds-arm") is scenario
    preset = presets.get("strong")
    predictor = preset.build_predictor(scenario)
    assert predictor.encoding.radius == encoding.reach_cells(scenario.robot) >= 5  # the patch covers the arm's reach
    folder = checkpoints.save_checkpoint(TrainedModels(scenario, preset, predictor), tmp_path / "arm")
    loaded = checkpoints.load_models(folder, "2ds-arm")
    ws = scenario.make_workspace(np.random.default_rng(0))
    Q = scenario.robot.sample(np.random.default_rng(1), 100)
    np.testing.assert_allclose(
        LearnedChecker(ws, loaded).probability(Q),
        LearnedChecker(ws, TrainedModels(scenario, preset, predictor)).probability(Q),
        rtol=1e-5,
    )


def test_register_refuses_clashes_and_robots_that_do_not_fit():
    with pytest.raises(ValueError, match="replace=True"):
        scenarios.register(dataclasses.replace(scenarios.get("2ds"), title="another"))
    with pytest.raises(ValueError, match="2D robot"):
        scenarios.register(dataclasses.replace(arm_scenario(), family="3dc", grid_shape=(11, 11, 11)))
    with pytest.raises(ValueError, match="grid"):
        scenarios.register(dataclasses.replace(arm_scenario(), grid_shape=(20, 20)))
    with pytest.raises(ValueError, match="family"):
        scenarios.register(dataclasses.replace(arm_scenario(), family="moon"))
    with pytest.raises(ValueError, match="unknown scenario"):
        scenarios.get("2ds-arm")


# -- the add_a_sampler tutorial's sampler, from the command line ---------------------------------------------------

TUTORIAL = Path(__file__).resolve().parents[1] / "tutorials" / "add_a_sampler.ipynb"
TUTORIAL_IMPORTS = """import numpy as np

from toolkit.planning.local_planner import last_valid_along, segment_points
from toolkit.planning.sampling import Sampler, register_sampler
"""


@pytest.fixture
def tutorial_sampler(tmp_path, monkeypatch):
    """The tutorial's ``MA`` sampler, its cell as written, saved as a module a user would pass to ``--import``."""
    cell = next(
        "".join(c["source"])
        for c in json.loads(TUTORIAL.read_text())["cells"]
        if c["cell_type"] == "code" and "class ChordMidpointSampler" in "".join(c["source"])
    )
    module = tmp_path / "my_samplers.py"
    module.write_text(TUTORIAL_IMPORTS + cell.replace("print(sorted(sampling.SAMPLERS))", ""))
    monkeypatch.delitem(sys.modules, "my_samplers", raising=False)
    return module


def test_the_tutorials_sampler_plans_from_the_command_line(tutorial_sampler, capsys):
    assert "MA" not in sampling.SAMPLERS
    assert (
        cli.main(
            ["plan", "--import", str(tutorial_sampler), "--scenario", "2ds", "--sampler", "MA", "--seed", "3", "--json"]
        )
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    assert out["sampler"] == "MA" and out["success"]
    assert sampling.SAMPLERS["MA"].__name__ == "ChordMidpointSampler"
    ws, robot = Workspace.from_dict(out["workspace"]), scenarios.get("2ds").robot
    assert path_is_valid(exact_checker(ws, robot), np.array(out["path"]), default_resolution(robot) / REFINEMENT)


def test_the_tutorials_sampler_is_offered_in_help_and_refused_without_its_module(tutorial_sampler, capsys):
    with pytest.raises(SystemExit):
        cli.main(["--import", str(tutorial_sampler), "--help"])
    assert "\n  MA    " in capsys.readouterr().out  # listed, with its docstring's first line
    del sampling.SAMPLERS["MA"]  # as a new process that was not given --import
    with pytest.raises(SystemExit) as exit_info:
        cli.main(["plan", "--scenario", "2ds", "--sampler", "MA"])
    assert exit_info.value.code == 2 and "invalid choice: 'MA'" in capsys.readouterr().err
    assert cli.main(["plan", "--import", "no_such_module_here", "--scenario", "2ds"]) == 2
    assert "--import no_such_module_here: No module named 'no_such_module_here'" in capsys.readouterr().err


def test_the_tutorials_sampler_is_offered_by_the_viewer(tutorial_sampler, make_viewer):
    from toolkit import viewer

    plugins.import_module(str(tutorial_sampler))
    panel = viewer.Panel(make_viewer("2ds"))
    assert "MA" in panel.sampler.options and "MA" in panel.planner_sampler.options
    assert panel.viewer.plan("MA", seed=0).success


@pytest.mark.slow
def test_the_tutorials_sampler_reproduces_in_worker_processes(tutorial_sampler, tmp_path):
    """``reproduce --samplers`` with a registered sampler: the planning workers import the module again."""
    out = tmp_path / "run"
    assert (
        cli.main(
            [
                "reproduce",
                "--import",
                str(tutorial_sampler),
                "--scenario",
                "2ds",
                "--quick",
                "--samplers",
                "BS,MA",
                "--workers",
                "2",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    results = json.loads((out / "results.json").read_text())
    assert list(results["planning"]) == ["BS", "MA"]
    for mode in ("without", "with"):
        assert results["planning"]["MA"][mode]["path_valid_rate"] == 1.0
    assert "| 2ds | MA |" in (out / "tables.md").read_text()  # beside n/a where the paper has no figure
