"""The paper's online phase (§III-B): samplers, the local planner, the roadmap, and PRM with and without
prediction, every returned path checked exactly. Rests on :mod:`toolkit.geometry` and
:mod:`toolkit.scenarios` only: a learned checker is just another checker here.

Reading order:

1. :mod:`toolkit.planning.sampling` — the four samplers BS, OB, G, BT over any checker (+ register your own);
2. :mod:`toolkit.planning.local_planner` — straight-line edges checked at a motion resolution;
3. :mod:`toolkit.planning.roadmap` — nodes, edges, k nearest neighbours, shortest paths;
4. :mod:`toolkit.planning.planner` — the interface: a frozen ``Problem`` (exact checker, start, goal, sampler, the
   checker that decides samples, resolution), a planner (a ``name``, its own ``Params``, ``solve(problem, rng)``)
   and its ``PlanResult``;
5. :mod:`toolkit.planning.options` — the roadmap planners' parameters: ``PaperParams`` (Algorithm 1's),
   ``LazyParams`` (the lazy PRM's) and ``BatchedParams`` (the batched PRM's), none inheriting another's;
6. :mod:`toolkit.planning.query_roadmap` — what both roadmap planners share: one query's roadmap, its
   counters and trace, and the exact verification of a path (repairing what fails);
7. :mod:`toolkit.planning.paper_prm` — **Algorithm 1**, as the paper has it, on one page (planner ``paper``);
8. :mod:`toolkit.planning.lazy_prm` — the lazy PRM (planner ``lazy``): the best exact roadmap planner, and
   prediction beyond the paper;
9. :mod:`toolkit.planning.batched_prm` — the batched PRM (planner ``batched``): the lazy PRM with each round's
   samples decided in one checker call, a device call when the checker is on a device;
10. :mod:`toolkit.planning.rrt_connect` — RRT-Connect (planner ``rrt-connect``): two trees, for a single query the
    fastest exact planner; each tree-growing move (nearest node, the segment with its angles wrapped, its points in
    the order checked) one compiled call of :mod:`toolkit.planning.rrt_kernels`;
11. :mod:`toolkit.planning.prm` — the planners by name (``register``, ``get``, ``names``; ``DEFAULT``, the rule for
    which runs) and ``plan(exact, start, goal, ...)``, one entry to any of them;
12. :mod:`toolkit.planning.ompl` — our checkers and samplers inside OMPL, for comparison.

The paper's query sets, one query built from a scenario (``toolkit.experiments.problems.build``) and
which planner a recipe's runs use are the experiments' business (:mod:`toolkit.experiments`).
"""
