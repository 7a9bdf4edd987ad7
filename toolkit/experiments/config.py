"""One run's configuration, built once — from the command line or a notebook — and passed down.

A run of the toolkit is one of the paper's scenarios (§IV-A), a training recipe
(a preset, §IV-B3), a seed from which every random draw follows, a size: the
paper's counts, or *quick*, and what Table 3 compares prediction against
(:data:`BASELINES`). :class:`RunConfig` holds them as objects, resolved from
their names once (``RunConfig.create("2ds", "paper", seed=0, quick=True)``), and
every stage of a run reads what it needs from it: how many workspaces to label,
which preset to train, how many queries to plan, how many processes to plan in.

Quick runs exist so that a test, a notebook in quick mode (``TOOLKIT_QUICK=1``) or
a first try finishes in seconds. They change sizes only, never which code runs,
and every size they change is in :data:`QUICK`, here.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

from toolkit import scenarios
from toolkit.experiments import planners
from toolkit.learning import presets
from toolkit.learning.presets import Preset
from toolkit.planning import prm, sampling
from toolkit.scenarios import Scenario


@dataclass(frozen=True)
class QuickSizes:
    """How a quick run shrinks a full one: every quick size of the toolkit, in one place."""

    workspaces: tuple[int, int, int] = (8, 4, 4)  # seen (training), seen-test, unseen workspaces
    cae_epochs_divisor: int = 50  # the preset's CAE epochs / this (at least 1)
    mlp_epochs_divisor: int = 10  # the preset's MLP epochs / this (at least 2)
    samples_factor: int = 4  # at most this many times the paper's labelled samples per workspace
    cae_workspaces: int = 40  # at most this many generated grids for the CAE
    cae_max_steps: int = 20  # at most this many CAE training steps
    queries: Mapping[str, tuple[int, int]] = field(  # (workspaces, pairs each) by scenario
        default_factory=lambda: MappingProxyType({"2ds": (2, 2), "3do": (1, 2), "3dc7": (3, 1), "3dc9": (3, 1)})
    )
    default_queries: tuple[int, int] = (2, 1)  # for a scenario of your own
    plan_samples: Mapping[str, int] = field(  # |S| where the paper's would take minutes
        default_factory=lambda: MappingProxyType({"3do": 400})
    )
    max_rounds: int = 5  # quick models predict poorly: planning gives up sooner
    throughput_repeats: int = 3  # timed calls per checker (a full run: 7)
    study_seen: int = 12  # ablation rows that ask for more training workspaces get this many
    study_epochs_divisor: int = 10  # tuning trains a tenth of each candidate's epochs
    # `toolkit bench --crossover --quick`: CrossoverSizes' fields (two values a variable, short calls, one round)
    crossover: Mapping[str, Any] = field(
        default_factory=lambda: MappingProxyType(
            {
                "obstacles": (10, 100),
                "subdivisions": (0, 2),
                "joints": (1, 3),
                "batches": (1, 100),
                "batch": 500,
                "mesh_batch": 100,
                "repeats": 1,
            }
        )
    )

    def shrink(self, preset: Preset) -> Preset:
        """The same recipe with few epochs and samples (marked ``quick``, so a checkpoint remembers it)."""
        if preset.quick:
            return preset
        return replace(
            preset,
            quick=True,
            cae_epochs=max(1, preset.cae_epochs // self.cae_epochs_divisor),
            mlp_epochs=max(2, preset.mlp_epochs // self.mlp_epochs_divisor),
            samples_factor=min(preset.samples_factor, self.samples_factor),
            cae_workspaces=min(preset.cae_workspaces, self.cae_workspaces),
            cae_max_steps=min(preset.cae_max_steps, self.cae_max_steps),
        )


QUICK = QuickSizes()

BASELINES = {  # what "without prediction" is in a reproduction's Table 3 (RunConfig.baseline; --baseline)
    "best": "the best exact planner (the lazy PRM) with the fastest exact checker (`exact_checker`: compiled)",
    "paper": "the paper's Algorithm 1 (as we read it, every candidate edge checked as it is added) with the fastest "
    "exact checker (`exact_checker`: compiled)",
    "paper-fcl": "the paper's Algorithm 1 with the python-fcl checker, a checker called from Python (the paper names "
    "none; with prediction, exact checks still use the fastest checker)",
    "paper-fcl-alike": "the paper's Algorithm 1 with the python-fcl checker, and prediction's exact checks with "
    "python-fcl too: one slow exact checker on both sides, as the paper's may have been (it names none)",
}
FCL_BASELINES = ("paper-fcl", "paper-fcl-alike")  # Table 3's baseline checks with python-fcl
FCL_ALIKE = "paper-fcl-alike"  # ... and so do prediction's exact checks (edges, paths)


def default_baseline(preset: Preset) -> str:
    """Table 3's baseline unless one is chosen: the planner paired with the recipe, without prediction
    (:mod:`toolkit.experiments.planners`; the ``paper`` preset's is Algorithm 1, so its Table 3 compares what the
    paper compares), with the default exact checker."""
    return "paper" if planners.pairing(preset).planner == "paper" else "best"


@dataclass(frozen=True, kw_only=True)
class RunConfig:
    """A scenario, a preset (already shrunk when ``quick``), a seed, and how to run: built once, read everywhere.

    Build it with :meth:`create`, which resolves names and checks values (and chooses Table 3's baseline)."""

    scenario: Scenario
    preset: Preset
    baseline: str  # Table 3's "without prediction": a name of BASELINES (create: default_baseline(preset))
    seed: int = 0
    quick: bool = False
    workers: int | None = None  # processes for planning (None: one per core; 1: all in this process)
    progress: bool = True  # progress bars
    device: str | None = None  # torch device for training and for the learned checker in planning and throughput
    #   (None: training on CUDA when present, else the CPU; the learned checker where the trained models are)
    planner: str | None = None  # Table 3's planner with and without prediction alike (None: each mode's own,
    #   planning_modes); a name of toolkit.planning.prm.names(), e.g. "batched"
    samplers: tuple[str, ...] = sampling.PAPER_SAMPLERS  # planned for Table 3: the paper's four, or registered ones
    imports: tuple[str, ...] = ()  # modules that register samplers, presets or scenarios (`toolkit --import`):
    #   a worker process imports them again, since it starts without what the parent registered

    @classmethod
    def create(
        cls,
        scenario: str | Scenario,
        preset: str | Preset = "paper",
        *,
        seed: int = 0,
        quick: bool = False,
        workers: int | None = None,
        progress: bool = True,
        device: str | None = None,
        samplers: tuple[str, ...] = sampling.PAPER_SAMPLERS,
        imports: tuple[str, ...] = (),
        baseline: str | None = None,
        planner: str | None = None,
        **preset_changes,
    ) -> RunConfig:
        """Resolve names (``scenarios.get``, ``presets.get``, the sampler registry) once; ``preset_changes`` replace
        preset fields after quick shrinking (e.g. ``cae_epochs=5``). A seed is a whole number in ``0 .. 2**32 - 1``;
        ``baseline`` a name of :data:`BASELINES` (None: :func:`default_baseline` of the preset); ``planner`` a
        registered planner's name."""
        samplers = sampling.check_names(samplers)
        scenario = scenarios.get(scenario) if isinstance(scenario, str) else scenario
        recipe = presets.get(preset) if isinstance(preset, str) else preset
        recipe = QUICK.shrink(recipe) if quick else recipe
        if unknown := sorted(set(preset_changes) - set(Preset.__dataclass_fields__)):
            raise ValueError(f"unknown preset setting(s) {unknown}")
        if int(seed) != seed or not 0 <= seed < 2**32:
            raise ValueError(f"seed must be a whole number in 0..{2**32 - 1}, got {seed!r}")
        if workers is not None and workers < 1:
            raise ValueError(f"workers must be 1 or more, got {workers!r}")
        if planner is not None:
            prm.get(planner)  # an unknown name: a one-line error listing the known
        if baseline is not None and baseline not in BASELINES:
            raise ValueError(f"unknown baseline {baseline!r}; choose one of {', '.join(BASELINES)}")
        return cls(
            scenario=scenario,
            preset=replace(recipe, **preset_changes),
            baseline=baseline or default_baseline(recipe),
            seed=int(seed),
            quick=bool(quick),
            workers=workers,
            progress=progress,
            device=device,
            planner=planner,
            samplers=tuple(samplers),
            imports=tuple(imports),
        )

    def settings(self) -> dict:
        """What makes the run, as ``results.json`` records it: a folder holding another run's cache is refused."""
        return {
            "scenario": self.scenario.name,
            "preset": self.preset.name,
            "quick": self.quick,
            "seed": self.seed,
            "baseline": self.baseline,
            **({"planner": self.planner} if self.planner else {}),  # only when named: older caches stay this run's
        }

    def workspace_counts(self) -> dict[str, int]:
        """Training, seen-test and unseen workspaces (``data.make_splits``' counts): the paper's unless quick or the
        preset asks for more training workspaces."""
        if self.quick:
            return dict(zip(("n_seen", "n_seen_test", "n_unseen"), QUICK.workspaces))
        return {"n_seen": self.preset.n_seen} if self.preset.n_seen else {}

    def samples_per_workspace(self) -> int:
        """Labelled configurations per workspace: the paper's times the preset's factor."""
        return self.scenario.samples_per_workspace * self.preset.samples_factor

    def query_counts(self) -> tuple[int | None, int | None]:
        """Planning queries as (workspaces, pairs each); None: the paper's (``queries.make_queries``' defaults)."""
        if not self.quick:
            return None, None
        return QUICK.queries.get(self.scenario.name, QUICK.default_queries)

    def planner_settings(self) -> dict:
        """Changes to the planners' parameters in this run: none at full size (each planner's own, with the
        scenario's |S|: :func:`toolkit.experiments.problems.make_planner`); fewer rounds and samples when quick."""
        if not self.quick:
            return {}
        return {
            "n_samples": QUICK.plan_samples.get(self.scenario.name, self.scenario.plan_samples),
            "max_rounds": QUICK.max_rounds,
        }

    def throughput_repeats(self) -> int:
        """Timed calls per checker in the reproduction's throughput stage."""
        return QUICK.throughput_repeats if self.quick else 7
