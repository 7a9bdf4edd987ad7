"""The lazy PRM (Bohlin & Kavraki 2000): the best exact planner, and with prediction the paper's future work.

:class:`LazyPRM`, the planner ``lazy``, is the paper's :class:`~toolkit.planning.paper_prm.PRM` with
two of its steps changed and parameters of its own (:class:`~toolkit.planning.options.LazyParams`);
sampling by the chosen checker, connecting to the k nearest, bridging, and the exact verification
and repair of every candidate path (:mod:`toolkit.planning.query_roadmap`) stay as they are, so
every returned path is still exactly valid at both resolutions.

**Edges are decided lazily** (:meth:`LazyPRM.decide`). Algorithm 1 checks every candidate edge
exactly, point by point, as it is added; most of those edges are never on the path. A lazy PRM
adds edges at the cost of their length and confirms them only when a candidate path uses them
(line 5's verification, which a lazy roadmap needs anyway). Two ways to decide an edge:

- *exact lazy edges* (no prediction, or ``screen_edges=False``): as edges are added, the exact
  checker looks at a few points of each, ``lazy_screen`` resolutions apart, all edges in one
  call. A point in collision rejects an edge for certain, and the candidate paths that follow
  fail less often (each failure costs a shortest-path search and a few small checker calls).
- *learned edge screening* (with prediction and ``screen_edges=True``, the default; the paper's
  stated future work): prediction instead of those few exact checks. Every edge is screened by
  batched prediction at points ``screen_spacing`` resolutions apart, an estimate of the fraction
  of it in collision: edges mostly predicted in collision (``screen_reject``) are dropped, the
  rest cost more the more of them is predicted in collision (``screen_penalty``). Each remembers
  the one point where screening predicted a collision (the middle predicted-invalid point,
  ``Roadmap.edge_suspect``): verification looks there first (``local_planner.refute_at``), since
  a screened edge that fails usually fails there, for one exact check instead of a
  certificate's several calls.

**Rounds grow** (:meth:`LazyPRM.round_size`): the first draws ``first_samples`` attempts, each
later round twice as many, up to |S| = ``n_samples``, so an easy query is solved on a small
roadmap; Algorithm 1 draws |S| every round.

With prediction, rounds after the first sample as ``auxiliary`` says (both planners read it):
the lazy PRM's default, ``"confirmed"``, samples with prediction and keeps what the exact
checker confirms, and every ``exact_every``-th round samples exactly; either keeps the planner
probabilistically complete however poor the prediction.

So "with / without prediction" on the lazy PRM compares the same planner, with the same rounds,
with and without prediction: only the checker differs. Checking many configurations in one call
is what makes our checkers fast (a call's fixed cost dwarfs a configuration's), so the planner
asks in batches wherever it can. What each choice buys, measured, is in ``docs/benchmarks.md``
("Planner design", "Against OMPL").
"""

from __future__ import annotations

import numpy as np

from toolkit.planning.local_planner import invalid_fractions
from toolkit.planning.options import LazyParams
from toolkit.planning.paper_prm import PRM
from toolkit.planning.query_roadmap import QueryRoadmap


class LazyPRM(PRM):
    """Algorithm 1 with lazy edges (exact or screened by prediction) and growing rounds."""

    name = "lazy"
    Params = LazyParams  # type: ignore[assignment]  # its own parameters, not Algorithm 1's

    def round_size(self, query: QueryRoadmap) -> int:
        """Sampler attempts this round: ``first_samples`` doubled each round up to |S| (None: |S| every round)."""
        n, first = self.params.n_samples, self.params.first_samples
        return n if first is None else min(n, first << min(int(query.stats["rounds"]) - 1, 30))

    def decide(self, query: QueryRoadmap, pairs: np.ndarray) -> None:
        """Add the candidate edges ``pairs (C, 2)`` that screening (with prediction) or a few exact checks accept,
        unconfirmed; remember the others as rejected."""
        options = self.params
        Q0, Q1 = query.roadmap.nodes[pairs.T]  # (C, dof) each
        length = query.roadmap.distance(Q0, Q1)  # (C,)
        if query.predicted and options.screen_edges:  # learned edge screening: one batched prediction for all
            fraction, suspect = invalid_fractions(query.checker, Q0, Q1, query.resolution * options.screen_spacing)
            cost = length * (1 + options.screen_penalty * fraction)  # (C,) the more predicted invalid, the dearer
            query.add_decided(pairs, fraction <= options.screen_reject, cost, suspect=suspect)
            return
        keep = np.ones(len(pairs), dtype=bool)  # exact lazy edges: a few exact checks now, in one call
        if options.lazy_screen is not None:
            keep = invalid_fractions(query.exact, Q0, Q1, query.resolution * options.lazy_screen)[0] == 0
        query.add_decided(pairs, keep, length)
