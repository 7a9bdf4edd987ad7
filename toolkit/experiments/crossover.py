"""Where does prediction pay? An exact check's cost against the network's, as what makes the check dear grows.

The paper's framework pays when the network answers "is this sample valid?" for less
than the exact checker does (§III-B, "Sample's Validity"; §V). The network's cost per
configuration is set by its sizes: it does not grow with the obstacles or the mesh (the
workspace is encoded once), and with the robot only through the input's width. An exact
check grows with what it must test. So this experiment varies, one at a time, what makes an
exact check expensive (:data:`VARIABLES`):

- ``obstacles``: unit blocks in the scenario's region (3DC has 110-125);
- ``triangles``: one icosphere obstacle, subdivided: a mesh workspace (its default exact checker compiled,
  its reference python-fcl's BVH with numpy winding numbers, ``MeshChecker``);
- ``links``: box chains of 1 to 15 joints (the paper's have 1 and 3: :func:`chain`);
- ``batch``: configurations a call (a sampler asks for 200-2,000 at a time);

and measures microseconds per configuration of the default exact checker
(``exact_checker``: compiled, for box worlds and meshes), of the python-fcl reference (``MeshChecker`` for a mesh)
and of the learned checker (untrained networks of the preset's sizes,
:func:`toolkit.experiments.bench.untrained_models`: their cost does not depend on their
weights), the three timed in turns (:func:`~toolkit.experiments.bench.in_turns`) on the same
uniform configurations, on one thread (as planning is timed: ``queries.one_thread``), the
exact answers held to FCL's. :func:`crossing` finds where
two cost curves cross, :func:`conclusion` says in words where the network is the cheaper check on this machine,
where the dearer, and where the two are too close to tell.

``toolkit bench --crossover [--scenario S] [--out DIR]``; the figure is
:func:`toolkit.plots.crossover`; results and their reading: ``docs/benchmarks.md``.

``--device cpu|cuda`` sweeps the batch on one device instead: :mod:`toolkit.experiments.on_device`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
import trimesh

from toolkit.experiments import bench
from toolkit.experiments.config import QUICK
from toolkit.experiments.queries import one_thread
from toolkit.geometry.collision import FCLChecker, MeshChecker, exact_checker
from toolkit.geometry.robots import BIG, CHAIN_JOINT_LIMITS, SMALL, BoxRobot, Joint
from toolkit.geometry.workspace import MeshWorkspace, Workspace, from_mesh
from toolkit.learning.learned import LearnedChecker
from toolkit.learning.presets import Preset
from toolkit.learning.training import TrainedModels
from toolkit.scenarios import Scenario
from toolkit.util.verdicts import CHEAPER, CLOSE, DEARER, NEAR, cost_verdict

VARIABLES = {  # what is varied -> the axis label
    "obstacles": "obstacles per workspace (unit blocks)",
    "triangles": "triangles of the mesh obstacle",
    "links": "links of the robot (box chain)",
    "batch": "configurations per call",
}
CHECKERS = ("exact", "fcl", "learned")  # default exact (compiled for box worlds), python-fcl, the network


@dataclass(frozen=True)
class CrossoverSizes:
    """The values each variable takes, the configurations a call where the batch is not varied (fewer against a
    mesh, whose exact check costs 50 µs to milliseconds a configuration), timed rounds."""

    obstacles: tuple[int, ...] = (10, 25, 50, 100, 200, 350, 500)
    subdivisions: tuple[int, ...] = (0, 1, 2, 3, 4)  # icosphere: 20 * 4**s triangles
    joints: tuple[int, ...] = (1, 3, 5, 9, 15)  # links: one more than the joints
    batches: tuple[int, ...] = (1, 10, 100, 1_000, 10_000)
    batch: int = 10_000
    mesh_batch: int = 1_000
    repeats: int = 7

    @classmethod
    def quick(cls) -> CrossoverSizes:
        """Two small values a variable and short calls (``config.QUICK.crossover``): a test's sizes."""
        return cls(**QUICK.crossover)


@dataclass(frozen=True)
class Setting:
    """A point: the variable's ``value``, a workspace, a scenario (its robot, the networks' sizes), a batch, and
    the calls a timed round makes (several for small batches, whose single calls are too short to time)."""

    value: int
    workspace: Workspace
    scenario: Scenario
    batch: int
    calls: int = 1


def chain(n_joints: int, region=(11.0, 11.0, 11.0)) -> BoxRobot:
    """A box chain with 6 base DoF and ``n_joints`` joints: small and big links in turn, turning about z, y, z, ...
    (``robots.box_chain(1)`` and ``box_chain(3)`` are the paper's 7- and 9-DoF chains, the same as these)."""
    if int(n_joints) != n_joints or n_joints < 1:
        raise ValueError(f"a chain needs a whole number of joints, 1 or more; got {n_joints!r}")
    links = [(SMALL, BIG)[i % 2] for i in range(n_joints + 1)]
    joints = [
        Joint((2 * link.half_extents[0], 0.0, 0.0), "zy"[i % 2], CHAIN_JOINT_LIMITS)
        for i, link in enumerate(links[:-1])
    ]
    region = np.asarray(region, dtype=float)
    return BoxRobot(f"chain{6 + n_joints}", "free", links, joints, position_bounds=(np.zeros(3), region))


def unit_blocks(region: Workspace, count: int, rng: np.random.Generator) -> Workspace:
    """``count`` unit blocks in distinct unit cells of ``region``'s box (as 3DC draws its 110-125)."""
    shape = region.grid_shape
    if not 0 <= count <= np.prod(shape):
        raise ValueError(f"{count} unit blocks do not fit in {np.prod(shape)} unit cells")
    cells = rng.choice(int(np.prod(shape)), size=count, replace=False)
    corners = region.lower + np.stack(np.unravel_index(cells, shape), axis=-1)  # (K, D)
    return Workspace(region.lower, region.upper, np.stack([corners, corners + 1.0], axis=1), family="blocks")


def sphere(region: Workspace, subdivisions: int) -> MeshWorkspace:
    """An icosphere of ``20 * 4**subdivisions`` triangles in the middle of ``region``, its radius 0.3 x the
    shortest side: a mesh workspace, whose default exact check is compiled (``CompiledMeshChecker``) and whose
    reference (``MeshChecker``) is FCL's BVH against the triangles and, for links that touch none, a numpy
    winding-number test of whether they lie inside."""
    mesh = trimesh.creation.icosphere(
        subdivisions=subdivisions, radius=0.3 * float(np.min(region.upper - region.lower))
    )
    mesh.apply_translation((region.lower + region.upper) / 2)
    return from_mesh(mesh, lower=region.lower, upper=region.upper, family="sphere")


def settings(scenario: Scenario, variable: str, sizes: CrossoverSizes, seed: int = 0) -> Iterator[Setting]:
    """The settings ``variable`` takes, all else the scenario's (its first query workspace, its robot)."""
    ws = scenario.workspaces("query", 1, seed)[0]
    if variable == "obstacles":
        rng = np.random.default_rng(seed)
        for count in sizes.obstacles:
            yield Setting(count, unit_blocks(ws, count, rng), scenario, sizes.batch)
    elif variable == "triangles":
        for level in sizes.subdivisions:
            yield Setting(20 * 4**level, sphere(ws, level), scenario, sizes.mesh_batch)
    elif variable == "links":
        for n in sizes.joints:
            robot = chain(n, ws.upper - ws.lower)
            yield Setting(n + 1, ws, dataclasses.replace(scenario, name=robot.name, robot=robot), sizes.batch)
    elif variable == "batch":
        for batch in sizes.batches:  # a round checks at least a tenth of sizes.batch configurations
            yield Setting(batch, ws, scenario, batch, calls=max(1, -(-sizes.batch // 10 // batch)))
    else:
        raise ValueError(f"unknown variable {variable!r}; choose from {', '.join(VARIABLES)}")


def variables_of(scenario: Scenario) -> tuple[str, ...]:
    """The variables that apply: in 2D only obstacles and the batch (no meshes, a lone point robot)."""
    return tuple(VARIABLES) if scenario.robot.dim == 3 else ("obstacles", "batch")


def measure(setting: Setting, models: TrainedModels, repeats: int, seed: int = 0) -> dict:
    """Microseconds per configuration of each checker on ``setting.batch`` uniform configurations, timed in turns;
    ``disagreements``: configurations the default exact checker answers differently from FCL (a mesh: from the
    reference ``MeshChecker``, FCL's BVH and numpy winding numbers); ``valid``: the fraction FCL calls valid."""
    robot, ws = setting.scenario.robot, setting.workspace
    Q = robot.sample(np.random.default_rng(seed), setting.batch)  # (batch, dof)
    checkers = {"exact": exact_checker(ws, robot), "learned": LearnedChecker(ws, models)}
    checkers["fcl"] = MeshChecker(ws, robot) if isinstance(ws, MeshWorkspace) else FCLChecker(ws, robot)
    n = setting.calls

    def call(checker):
        return (lambda: [checker.are_valid(Q) for _ in range(n)]), n * len(Q)

    rates = bench.in_turns({name: call(checker) for name, checker in checkers.items()}, repeats)
    truth = checkers["fcl"].are_valid(Q)  # (batch,)
    return {
        **{f"{name}_us": 1e6 / rates[name] if name in rates else None for name in CHECKERS},
        "disagreements": int((checkers["exact"].are_valid(Q) != truth).sum()),
        "valid": float(truth.mean()),
    }


def sweep(scenario: Scenario, variable: str, *, sizes: CrossoverSizes, preset: Preset, seed: int = 0) -> dict:
    """One variable's measurements as columns (``values``, ``exact_us``, ``fcl_us``, ``learned_us``,
    ``disagreements``, ``valid``), and where the learned curve crosses each exact one (:func:`crossing`)."""
    models: dict[str, TrainedModels] = {}  # by scenario name: the chains need networks of their own DoF
    rows = []
    for setting in settings(scenario, variable, sizes, seed):
        name = setting.scenario.name
        if name not in models:
            models[name] = bench.untrained_models(setting.scenario, preset, seed)
        rows.append({"value": setting.value, **measure(setting, models[name], sizes.repeats, seed)})
    columns = {key: [row[key] for row in rows] for key in rows[0]}
    columns["values"] = columns.pop("value")
    return {
        "label": VARIABLES[variable],
        **columns,
        "crossing": {
            name: crossing(columns["values"], columns[f"{name}_us"], columns["learned_us"]) for name in ("exact", "fcl")
        },
    }


def crossover(
    scenario: Scenario,
    preset: Preset,
    *,
    seed: int = 0,
    quick: bool = False,
    variables: tuple[str, ...] = (),
    sizes: CrossoverSizes | None = None,
) -> dict:
    """Every variable that applies (or those named), swept on ``scenario`` at ``sizes`` (default: the full ones, or
    :meth:`CrossoverSizes.quick` where ``quick``): ``{"scenario", "preset", "quick", "seed", "batch", "mesh_batch",
    "variables": {name: sweep}, "conclusion": [lines]}``."""
    if sizes is None:
        sizes = CrossoverSizes.quick() if quick else CrossoverSizes()
    applicable = variables_of(scenario)
    if unknown := sorted(set(variables) - set(applicable)):
        raise ValueError(f"variable(s) {unknown} do not apply to {scenario.name}; choose from {', '.join(applicable)}")
    with one_thread():
        sweeps = {v: sweep(scenario, v, sizes=sizes, preset=preset, seed=seed) for v in variables or applicable}
    results = {
        "scenario": scenario.name,
        "preset": preset.name,
        "quick": quick,
        "seed": seed,
        "batch": sizes.batch,
        "mesh_batch": sizes.mesh_batch,
        "variables": sweeps,
    }
    results["conclusion"] = conclusion(results)
    return results


def crossing(values: list, exact_us: list, learned_us: list) -> dict | None:
    """Where the learned cost per configuration meets an exact one, interpolated log-log between the two measured
    values around the first change of sign of ``log(exact / learned)``: ``{"value", "learned_wins_above"}`` (the
    side where the network is cheaper); None where they do not cross (or ``exact_us`` holds no figure)."""
    if any(e is None for e in exact_us):
        return None
    gap = np.log(np.asarray(exact_us, float) / np.asarray(learned_us, float))  # > 0: the network is cheaper
    x = np.log(np.asarray(values, float))
    for i in range(len(gap) - 1):
        if gap[i] == 0 or gap[i] * gap[i + 1] < 0:
            t = gap[i] / (gap[i] - gap[i + 1])
            return {"value": float(np.exp(x[i] + t * (x[i + 1] - x[i]))), "learned_wins_above": bool(gap[i + 1] > 0)}
    return None


COST_WORDS = {CHEAPER: "cheaper", NEAR: f"can't tell (within {CLOSE:.0%})", DEARER: "dearer"}  # cost_verdict's words


def conclusion(results: dict) -> list[str]:
    """In words, per variable, where the network costs less per configuration than the default exact checker, where
    more and where the two are too close to tell (:func:`toolkit.util.verdicts.cost_verdict`, the chapters' band),
    the same against python-fcl where it was timed, then the costs: the words never contradict the numbers."""
    lines = []
    for sweep_ in results["variables"].values():
        values, exact, fcl, learned = (sweep_[key] for key in ("values", "exact_us", "fcl_us", "learned_us"))
        said = [f"the network against the default exact check: {_compared(values, learned, exact)}"]
        costs = [f"default exact {_span(exact)}"]
        if all(f is not None for f in fcl):
            said.append(f"against python-fcl: {_compared(values, learned, fcl)}")
            costs.append(f"python-fcl {_span(fcl)}")
        costs.append(f"network {_span(learned)}")
        lines.append(f"{sweep_['label']}: {'; '.join(said)}. Cost a configuration, µs: {', '.join(costs)}.")
    return lines


def _compared(values: list, learned: list, exact: list) -> str:
    """``"cheaper at 10, 50 (0.54-0.7x its cost) and dearer at 500 (1.3x its cost)"``: the values grouped by
    :data:`COST_WORDS`, each group with its span of ratios (network / exact)."""
    ratio = np.asarray(learned, dtype=float) / np.asarray(exact, dtype=float)  # (values,)
    verdicts = [cost_verdict(float(r)) for r in ratio]
    groups = []
    for verdict, word in COST_WORDS.items():
        picked = [i for i, v in enumerate(verdicts) if v == verdict]
        if picked:
            where = "every value" if len(picked) == len(values) else ", ".join(f"{values[i]:,}" for i in picked)
            groups.append(f"{word} at {where} ({_span(ratio[picked])}x its cost)")
    return ", ".join(groups[:-1]) + (" and " if len(groups) > 1 else "") + groups[-1]


def _span(numbers) -> str:
    """``"0.27-0.29"``, ``"15-2200"``: the least and the most to two significant figures, one where they round alike."""
    low, high = (np.format_float_positional(f(numbers), precision=2, fractional=False, trim="-") for f in (min, max))
    return low if low == high else f"{low}-{high}"


def markdown(results: dict) -> str:
    """The sweeps as markdown tables (microseconds a configuration), then the conclusion."""
    lines = [
        f"# Crossover, {results['scenario']}, preset `{results['preset']}`{' (quick)' if results['quick'] else ''}"
    ]
    for sweep_ in results["variables"].values():
        lines += ["", f"| {sweep_['label']} | exact us | FCL us | learned us | learned / exact | valid | disagree |"]
        lines += ["| --- | --- | --- | --- | --- | --- | --- |"]
        for i, value in enumerate(sweep_["values"]):
            fcl, disagree = sweep_["fcl_us"][i], sweep_["disagreements"][i]
            lines.append(
                f"| {value:,} | {sweep_['exact_us'][i]:.3g} | {'n/a' if fcl is None else f'{fcl:.3g}'} "
                f"| {sweep_['learned_us'][i]:.3g} | {sweep_['learned_us'][i] / sweep_['exact_us'][i]:.2f} "
                f"| {sweep_['valid'][i]:.0%} | {'n/a' if disagree is None else disagree} |"
            )
    return "\n".join(lines + ["", *results["conclusion"], ""])
