"""`toolkit bench --crossover` (issue 25): where prediction pays, swept at quick sizes.

Costs are measured, never asserted (no timed unit tests); what is asserted: the sweep's
shape, the settings it builds, that every exact answer agrees with python-fcl, the crossing
and the conclusion computed from given figures, and the figure's axes.
"""

import dataclasses
import json

import numpy as np
import pytest
from matplotlib.figure import Figure

from toolkit import cli, plots, scenarios
from toolkit.experiments import crossover, on_device
from toolkit.experiments.config import QUICK
from toolkit.geometry import robots
from toolkit.geometry.workspace import MeshWorkspace
from toolkit.learning import presets
from toolkit.plots.crossover import LEGEND

QUICK_VALUES = {  # what each variable takes at quick sizes (config.QUICK.crossover)
    "obstacles": [10, 100],
    "triangles": [20, 320],  # icospheres of 0 and 2 subdivisions
    "links": [2, 4],  # chains of 1 and 3 joints
    "batch": [1, 100],
}
COLUMNS = {"label", "values", "exact_us", "fcl_us", "learned_us", "disagreements", "valid", "crossing"}


@pytest.fixture(scope="module")
def swept():
    return crossover.crossover(scenarios.get("3dc7"), presets.get("paper"), quick=True)


def test_a_quick_sweep_measures_every_variable_at_its_values(swept):
    assert swept["scenario"] == "3dc7" and swept["preset"] == "paper" and swept["quick"] is True
    assert swept["batch"] == QUICK.crossover["batch"] and swept["mesh_batch"] == QUICK.crossover["mesh_batch"]
    assert list(swept["variables"]) == list(crossover.VARIABLES)
    for name, sweep in swept["variables"].items():
        assert set(sweep) == COLUMNS
        assert sweep["values"] == QUICK_VALUES[name] and sweep["label"] == crossover.VARIABLES[name]
        assert all(us > 0 for key in ("exact_us", "learned_us") for us in sweep[key])
        assert all(0.0 <= v <= 1.0 for v in sweep["valid"])
        assert set(sweep["crossing"]) == {"exact", "fcl"}
    assert len(swept["conclusion"]) == len(swept["variables"])
    json.dumps(swept)  # crossover.json holds it as is


def test_every_exact_answer_agrees_with_fcl(swept):
    """A mesh's default exact checker (compiled) is held to its python-fcl reference (``MeshChecker``) too."""
    for name, sweep in swept["variables"].items():
        assert all(us > 0 for us in sweep["fcl_us"])
        assert sweep["disagreements"] == [0, 0], name


def test_the_settings_vary_one_thing_each():
    scenario, sizes = scenarios.get("3dc7"), crossover.CrossoverSizes.quick()
    blocks = list(crossover.settings(scenario, "obstacles", sizes))
    for setting, count in zip(blocks, QUICK_VALUES["obstacles"]):
        boxes = setting.workspace.boxes  # (K, 2, 3)
        assert len(boxes) == count and np.all(boxes[:, 1] - boxes[:, 0] == 1.0)
        assert len(np.unique(boxes[:, 0], axis=0)) == count  # distinct cells
        assert setting.scenario is scenario and setting.batch == sizes.batch
    spheres = list(crossover.settings(scenario, "triangles", sizes))
    assert all(isinstance(s.workspace, MeshWorkspace) for s in spheres)
    assert [len(s.workspace.faces) for s in spheres] == QUICK_VALUES["triangles"]
    chains = list(crossover.settings(scenario, "links", sizes))
    assert [s.scenario.robot.n_links for s in chains] == QUICK_VALUES["links"]
    assert [s.scenario.robot.dof for s in chains] == [7, 9]
    batches = list(crossover.settings(scenario, "batch", sizes))
    assert [(s.batch, s.calls) for s in batches] == [(1, 50), (100, 1)]  # a round checks >= batch / 10
    with pytest.raises(ValueError, match="unknown variable 'mass'"):
        list(crossover.settings(scenario, "mass", sizes))


@pytest.mark.parametrize("n_joints", [1, 3])
def test_the_chains_of_one_and_three_joints_are_the_papers(n_joints):
    ours, paper = crossover.chain(n_joints), robots.box_chain(n_joints)
    assert ours.name == paper.name and ours.dof == paper.dof
    np.testing.assert_array_equal(ours.lower, paper.lower)
    np.testing.assert_array_equal(ours.upper, paper.upper)
    Q = paper.sample(np.random.default_rng(0), 50)
    for a, b in zip(ours.link_boxes(Q), paper.link_boxes(Q)):
        np.testing.assert_allclose(a, b)


def test_sizes_of_ones_own_set_what_is_swept():
    sizes = dataclasses.replace(crossover.CrossoverSizes.quick(), obstacles=(5, 15, 40), batch=300)
    swept = crossover.crossover(scenarios.get("2ds"), presets.get("paper"), variables=("obstacles",), sizes=sizes)
    assert swept["quick"] is False and swept["batch"] == 300
    assert list(swept["variables"]) == ["obstacles"] and swept["variables"]["obstacles"]["values"] == [5, 15, 40]


def test_a_longer_chain_and_bad_sizes_are_named():
    long = crossover.chain(9)
    assert long.n_links == 10 and long.dof == 15
    with pytest.raises(ValueError, match="a whole number of joints, 1 or more; got 0"):
        crossover.chain(0)
    region = scenarios.get("3dc7").workspaces("query", 1, 0)[0]
    with pytest.raises(ValueError, match="2000 unit blocks do not fit in 1331 unit cells"):
        crossover.unit_blocks(region, 2000, np.random.default_rng(0))


def test_2d_sweeps_obstacles_and_the_batch_only():
    assert crossover.variables_of(scenarios.get("2ds")) == ("obstacles", "batch")
    with pytest.raises(ValueError, match=r"variable\(s\) \['links'\] do not apply to 2ds"):
        crossover.crossover(scenarios.get("2ds"), presets.get("paper"), quick=True, variables=("links",))


def test_crossing_interpolates_log_log_between_the_measured_values():
    # exact 1, 2, 4 us against a flat 3 us: the sign changes between 10 and 100
    found = crossover.crossing([1, 10, 100], [1.0, 2.0, 4.0], [3.0, 3.0, 3.0])
    t = np.log(2 / 3) / (np.log(2 / 3) - np.log(4 / 3))
    assert found == {"value": pytest.approx(10 ** (1 + t)), "learned_wins_above": True}
    assert crossover.crossing([1, 10], [1.0, 2.0], [3.0, 3.0]) is None  # the check stays cheaper
    assert crossover.crossing([1, 10], [None, None], [3.0, 3.0]) is None  # nothing to cross
    down = crossover.crossing([1, 10], [4.0, 1.0], [2.0, 2.0])  # the network wins below
    assert down == {"value": pytest.approx(10**0.5), "learned_wins_above": False}


def test_the_conclusion_says_cheaper_dearer_or_cant_tell_as_the_numbers_beside_it_show():
    def sweep(label, exact, fcl, learned, values=(10, 100)):
        return {"label": label, "values": list(values), "exact_us": exact, "fcl_us": fcl, "learned_us": learned}

    lines = crossover.conclusion(
        {
            "variables": {
                "obstacles": sweep("obstacles", [1.0, 2.0], [10.0, 30.0], [3.0, 3.0]),  # dearer; cheaper than FCL
                "triangles": sweep("triangles", [4.0, 5.0], [None, None], [1.0, 1.0]),  # cheaper
                "links": sweep("links", [4.0, 4.0], [None, None], [3.0, 5.0]),  # 0.75, 1.25: the band's edges
                "batch": sweep("batch", [1.0, 1.0, 1.0], [None] * 3, [0.5, 1.0, 2.0], values=(10, 100, 1000)),
            }
        }
    )
    assert lines == [
        "obstacles: the network against the default exact check: dearer at every value (1.5-3x its cost); "
        "against python-fcl: cheaper at every value (0.1-0.3x its cost). "
        "Cost a configuration, µs: default exact 1-2, python-fcl 10-30, network 3.",
        "triangles: the network against the default exact check: cheaper at every value (0.2-0.25x its cost). "
        "Cost a configuration, µs: default exact 4-5, network 1.",
        "links: the network against the default exact check: can't tell (within 25%) at every value "
        "(0.75-1.2x its cost). Cost a configuration, µs: default exact 4, network 3-5.",
        "batch: the network against the default exact check: cheaper at 10 (0.5x its cost), can't tell (within "
        "25%) at 100 (1x its cost) and dearer at 1,000 (2x its cost). Cost a configuration, µs: default "
        "exact 1, network 0.5-2.",
    ]


def test_the_figure_has_a_log_log_panel_per_variable(swept):
    fig = plots.crossover(swept)
    assert isinstance(fig, Figure)
    shown = [ax for ax in fig.axes if ax.get_visible()]
    assert [ax.get_xlabel() for ax in shown] == list(crossover.VARIABLES.values())
    for ax, sweep in zip(shown, swept["variables"].values()):
        assert ax.get_xscale() == ax.get_yscale() == "log"
        assert ax.get_ylabel() == "µs per configuration"
        lines = {line.get_label(): line for line in ax.get_lines() if not line.get_label().startswith("_")}
        assert set(LEGEND.values()) <= set(lines)  # each checker's curve, named as the legend says
        np.testing.assert_allclose(lines[LEGEND["learned"]].get_ydata(), sweep["learned_us"])


def test_bench_crossover_prints_json_and_writes_the_figure(tmp_path, capsys):
    out = tmp_path / "figures"
    args = ["bench", "--crossover", "--quick", "--scenario", "2ds", "--variables", "batch", "--out", str(out)]
    assert cli.main(args + ["--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert list(printed["variables"]) == ["batch"] and printed["scenario"] == "2ds"
    assert json.loads((out / "crossover.json").read_text()) == printed
    assert (out / "crossover.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert cli.main(["bench", "--crossover", "--quick", "--scenario", "2ds", "--variables", "links"]) == 2
    assert "do not apply to 2ds" in capsys.readouterr().err


def test_on_one_device_every_checker_is_timed_at_every_point_and_the_exact_answers_agree(tmp_path, capsys):
    """`bench --crossover --device cpu --quick` (on a GPU the same with cuda): the batch, obstacles and links swept
    on one device, every column timed, the exact check on the device answering as the compiled one, the fastest
    and the conclusion read from the figures; meshes are refused by name."""
    out = tmp_path / "device"
    args = ["bench", "--crossover", "--quick", "--scenario", "3dc7", "--device", "cpu", "--out", str(out), "--json"]
    assert cli.main(args) == 0
    found = json.loads(capsys.readouterr().out)
    assert json.loads((out / "crossover_device.json").read_text()) == found
    assert found["device"] == "cpu" and list(found["variables"]) == list(on_device.VARIABLES)
    quick = crossover.CrossoverSizes.quick()
    expected = {"batch": list(on_device.QUICK_BATCHES), "obstacles": list(quick.obstacles), "links": [2, 4]}
    for variable, sweep in found["variables"].items():
        assert sweep["values"] == expected[variable], variable
        assert sweep["batch"] == (expected["batch"] if variable == "batch" else [quick.batch] * 2)
        for name in on_device.COLUMNS:
            assert all(us > 0 for us in sweep[f"{name}_us"])
        assert sweep["disagreements"] == [0, 0]
        for i, fastest in enumerate(sweep["fastest"]):
            assert sweep[f"{fastest}_us"][i] == min(sweep[f"{n}_us"][i] for n in on_device.COLUMNS)
    assert len(found["conclusion"]) == 6 and found["conclusion"][0].startswith("256 a call on cpu: cheapest is ")
    assert found["conclusion"][2].startswith("obstacles per workspace (unit blocks) 10 on cpu: cheapest is ")
    table = on_device.markdown(found)
    assert table.count("\n| 2,048 | 2,048 |") == 1 and "resident" in table and table.count("\n| --- | --- |") == 3
    assert cli.main(args[:-3] + ["--variables", "triangles"]) == 2
    assert "meshes stay on the CPU" in capsys.readouterr().err
