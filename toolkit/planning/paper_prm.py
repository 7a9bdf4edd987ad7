"""Algorithm 1 of the paper (§III-B, "SBMP Variant"): PRM with and without prediction, as the paper has it.

Read this page beside the paper's Algorithm 1; each of its five lines is marked in the code
(``# Algorithm 1, line N``):

1. the CAE encodes the workspace into ``z``: done once, when the learned checker was built
   (:class:`~toolkit.learning.learned.LearnedChecker`); the planner only sees a checker;
2. sample a set ``S`` of configurations with the chosen sampler (BS, OB, G, BT:
   :mod:`toolkit.planning.sampling`; |S| = ``n_samples`` attempts);
3. the checker keeps ``S'``, the samples it calls valid: the learned one ("with prediction"), or
   an exact one ("without"): the two modes differ in the problem's ``checker`` only;
4. a standard PRM on ``S'``: each node with its ``k`` nearest neighbours by straight-line edges,
   each **checked exactly**, point by point at the local planner's ``resolution``, as it is
   added (:meth:`PRM.decide`). If the roadmap does not join start and goal, "create additional
   valid samples using auxiliary samplers": another round of the same sampler, its samples
   checked exactly (``PaperParams.auxiliary``, ``"exact"`` by default);
5. extract a path from the roadmap, and (§III-B, "the path is extracted and verified") verify it
   with the exact checker, repairing what fails (:mod:`toolkit.planning.query_roadmap`).

Whatever the checker says about samples, a returned path has passed the exact checker at the
resolution and 10x finer (``Problem.fine_resolution``): a wrong prediction costs time, never a
wrong path.

:class:`PRM` is the planner ``paper`` (:mod:`toolkit.planning.planner`: a name, its own parameters,
:class:`~toolkit.planning.options.PaperParams`, and ``solve(problem, rng)``). It keeps the two steps
that a variant may change as methods: how many attempts a round samples (:meth:`PRM.round_size`),
how a sampler's attempts are drawn (:meth:`PRM.draw`) and how a candidate edge is decided
(:meth:`PRM.decide`); :class:`~toolkit.planning.lazy_prm.LazyPRM` changes the first and the last,
:class:`~toolkit.planning.batched_prm.BatchedPRM` the draws too.
"""

from __future__ import annotations

from functools import partial

import numpy as np

from toolkit.planning.local_planner import check_edges
from toolkit.planning.options import PaperParams
from toolkit.planning.planner import Planner, PlanResult, Problem
from toolkit.planning.query_roadmap import QueryRoadmap
from toolkit.planning.sampling import Sampler


class PRM(Planner):
    """The paper's PRM (Algorithm 1): ``PRM(params).solve(problem, rng)``."""

    name = "paper"
    Params = PaperParams  # the parameters this planner reads, and no other planner
    query_class = QueryRoadmap  # one query's state (a subclass: e.g. timed, toolkit.experiments.profile)

    def solve(self, problem: Problem, rng: np.random.Generator, *, trace: list | None = None) -> PlanResult:
        """One query; a ``trace`` list receives a ``PlanStep`` at every stage."""
        # Algorithm 1, line 1: a learned checker encoded the workspace (the CAE's z) when it was built
        query = self.query_class(problem, self.params, trace)
        decide = partial(self.decide, query)  # this planner's edge rule, for connecting and bridging
        new = query.add_endpoints()  # START, GOAL
        path = None
        while path is None and query.stats["rounds"] < self.params.max_rounds:
            query.stats["rounds"] += 1
            with query.timed("sampling_s", "node_checks"):
                kept, verified = self.sample_round(query, rng)  # S' (M, dof): lines 2-3, or line 4's auxiliary
            new = np.concatenate([new, query.roadmap.add_nodes(kept, verified=verified)])
            query.record("sample", new_nodes=new)
            # Algorithm 1, line 4: a standard PRM on S': k nearest neighbours, edges by this planner's rule
            with query.timed("connection_s", "edge_checks"):
                decide(query.roadmap.candidate_edges(new, self.params.k))
                query.bridge(decide)  # while start and goal lie apart: from their components
            query.record("connect")
            new = new[:0]
            # Algorithm 1, line 5: extract the cheapest path and verify it exactly (repairing what fails);
            # no path yet: line 4 again, "create additional valid samples using auxiliary samplers"
            path = query.extract_path(decide)
        return query.result(path, self.name)

    def round_size(self, query: QueryRoadmap) -> int:
        """Sampler attempts this round: |S| = ``n_samples``, every round."""
        return self.params.n_samples

    def sample_round(self, query: QueryRoadmap, rng: np.random.Generator) -> tuple[np.ndarray, bool]:
        """This round's ``S' (M, dof)`` and whether an exact checker vouches for them."""
        n, params, round_ = self.round_size(query), self.params, query.stats["rounds"]
        if not query.predicted:  # lines 2-3 without prediction: an exact checker keeps S'
            return self.draw(query.sampler, n, rng), True
        if round_ == 1 or params.auxiliary == "predicted":
            # Algorithm 1, line 2: the sampler draws S; line 3: the learned checker keeps S' (in batches)
            return self.draw(query.sampler, n, rng), False
        # Algorithm 1, line 4: "additional valid samples" from the auxiliary sampler, checked exactly
        if params.auxiliary == "exact" or (round_ - 1) % params.exact_every == 0:
            return self.draw(query.exact_sampler, n, rng), True
        S = self.draw(query.sampler, n, rng)  # "confirmed": prediction proposes, the exact checker confirms
        return S[query.exact.are_valid(S)], True

    def draw(self, sampler: Sampler, n: int, rng: np.random.Generator) -> np.ndarray:
        """``(M, dof)`` the samples of ``n`` attempts of ``sampler``, asking its checker as the sampler does."""
        return sampler.sample(n, rng)

    def decide(self, query: QueryRoadmap, pairs: np.ndarray) -> None:
        """Algorithm 1, line 4: add the candidate edges ``pairs (C, 2)`` that the exact checker accepts, point by
        point at the resolution, as they are added; remember the others as rejected."""
        Q0, Q1 = query.roadmap.nodes[pairs.T]  # (C, dof) each
        keep = check_edges(query.exact, Q0, Q1, query.resolution)  # (C,)
        query.add_decided(pairs, keep, query.roadmap.distance(Q0, Q1), checked_at=query.resolution)
