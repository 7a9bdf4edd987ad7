"""The paper's experiments (§IV-A, §V), reproduced and extended: where learning and planning meet.

Reading order:

1. :mod:`toolkit.experiments.planners` — which planner a training recipe's runs plan with (``paper``: Algorithm 1;
   ``strong``: the lazy PRM with learned edge screening), with and without its model alike;
2. :mod:`toolkit.experiments.query_sets` — the paper's query sets (§IV-A); :mod:`~toolkit.experiments.problems` —
   one query built once (``build``: scenario, query, checkers, the planner and its parameters);
   :mod:`~toolkit.experiments.queries` — runs over the queries (with and without prediction, in turns) and
   :mod:`~toolkit.experiments.summaries`, what they report;
3. :mod:`toolkit.experiments.config` — ``RunConfig``: one run's scenario, preset, seed, sizes (``QUICK``) and
   Table 3's baseline (``BASELINES``);
4. :mod:`toolkit.experiments.pipeline` — data, training, evaluation and a checkpoint, in one call;
5. :mod:`toolkit.experiments.paper_numbers` — the published figures;
6. :mod:`toolkit.experiments.reproduce` — ``toolkit reproduce``: Tables 1-3 and figures, resumable, built on
   :mod:`~toolkit.experiments.stages` (the stage cache), :mod:`~toolkit.experiments.workers` (planning
   processes that stop with their parent) and :mod:`~toolkit.experiments.tables` (the tables beside the paper's);
7. :mod:`toolkit.experiments.bench` — throughput and planner benchmarks (``toolkit bench``),
   :mod:`~toolkit.experiments.versus_ompl`, our planners against OMPL's on the same checker, and
   :mod:`~toolkit.experiments.crossover`, where prediction pays: exact against learned cost per configuration,
   and :mod:`~toolkit.experiments.survey`, chapter 01's scenarios measured beside the paper's;
8. :mod:`toolkit.experiments.ablation` — the paper's recipe to ours, one change at a time;
9. :mod:`toolkit.experiments.tuning` — the paper's unstated settings, chosen on held-out workspaces.
"""
