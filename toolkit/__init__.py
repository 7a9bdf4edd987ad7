"""Teaching toolkit for *Predicting Sample Collision with Neural Networks* (Tran, Denny, Ekenna).

Packages, in the order a reader meets them; each package's docstring is its own reading order,
and a package imports only from those above it (``docs/design.md``):

1. :mod:`toolkit.util` — small helpers: registries, thread limits, atomic outputs;
2. :mod:`toolkit.geometry` — robots, workspaces, and the exact answer to "is this configuration valid?";
3. :mod:`toolkit.scenarios` — the paper's four scenarios (2DS, 3DO, 3DC-7, 3DC-9);
4. :mod:`toolkit.learning` — the offline phase: data, the CAE and the MLP, the learned checker;
5. :mod:`toolkit.planning` — the online phase: samplers, the local planner, PRM with and without prediction;
6. :mod:`toolkit.plots` — every figure (each returns a matplotlib Figure);
7. :mod:`toolkit.experiments` — the paper's query sets and tables, benchmarks: where learning and planning meet;
8. :mod:`toolkit.viewer` — the Viser scene of the 3D workspaces;
9. :mod:`toolkit.teaching` — the notebooks' helpers and grading;
10. :mod:`toolkit.cli` — the ``toolkit`` command.
"""

__version__ = "0.1.0"
