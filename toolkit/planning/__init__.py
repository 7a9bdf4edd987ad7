"""The paper's online phase (§III-B): samplers, the local planner, the roadmap, and PRM with and without
prediction, every returned path checked exactly. Rests on :mod:`toolkit.geometry` and
:mod:`toolkit.scenarios` only: a learned checker is just another checker here.

Reading order:

1. :mod:`toolkit.planning.sampling` — the four samplers BS, OB, G, BT over any checker (+ register your own);
2. :mod:`toolkit.planning.local_planner` — straight-line edges checked at a motion resolution;
3. :mod:`toolkit.planning.roadmap` — nodes, edges, k nearest neighbours, shortest paths;
4. :mod:`toolkit.planning.options` — each planner's settings: ``PRMOptions`` (Algorithm 1's) and
   ``LazyPRMOptions`` (those and the lazy planner's own);
5. :mod:`toolkit.planning.query_roadmap` — what both planners share: one query's roadmap, its
   counters and trace, and the exact verification of a path (repairing what fails);
6. :mod:`toolkit.planning.paper_prm` — **Algorithm 1**, as the paper has it, on one page;
7. :mod:`toolkit.planning.lazy_prm` — the lazy PRM: the best exact planner, and prediction beyond the paper;
8. :mod:`toolkit.planning.rrt_connect` — RRT-Connect: two trees, for a single query the fastest exact planner;
9. :mod:`toolkit.planning.prm` — ``plan(exact, start, goal, ...)``: one entry to either planner, chosen by the
   options' class;
10. :mod:`toolkit.planning.ompl` — our checkers and samplers inside OMPL, for comparison.

Which planner plans with which model, and the paper's query sets, are the experiments' business
(:mod:`toolkit.experiments`).
"""
