"""Every figure of the toolkit: functions that return a matplotlib ``Figure``.

Nothing here calls ``show()`` and everything renders headless (Agg): a notebook
displays the returned figure, a script saves it (``fig.savefig(path)``). One module
per topic, in the order of the notebooks:

- :mod:`toolkit.plots.robot_drawing` — a robot's link boxes at configurations, among the blocks near it
  (notebooks 01, 05), each box drawn from its corners by :mod:`toolkit.plots.boxes`, where it touches or overlaps a
  block found by :mod:`toolkit.plots.contact`; one check's configurations side by side with the checker's verdict
  on each by :mod:`toolkit.plots.verdict` (notebook 01);
- :mod:`toolkit.plots.slices` — the grid of a 2-DoF slice of configuration space (notebooks 01, 03);
- :mod:`toolkit.plots.cspace` — workspaces, occupancy grids, configuration-space obstacles (notebook 01);
- :mod:`toolkit.plots.cae` — the contractive autoencoder's reconstructions and latents (notebook 02), the wrongly
  decoded cells marked by :mod:`toolkit.plots.wrong_cells`;
- :mod:`toolkit.plots.answers` — the collision MLP's answers against the truth: their kinds, counts, ROC points;
- :mod:`toolkit.plots.classifier` — the collision MLP's decision boundaries and thresholds (notebook 03);
- :mod:`toolkit.plots.cell_marks` — marks on a map's cells sized to be seen however fine the map (notebook 03),
  each drawn on one of its tile's mistakes by :mod:`toolkit.plots.mark_sides`;
- :mod:`toolkit.plots.planning` — samplers, roadmaps, a planner step by step (notebook 04);
- :mod:`toolkit.plots.timings` — planning times with and without prediction, checkers' throughputs (notebook 04);
- :mod:`toolkit.plots.scenes` — a planned 3D path, one frame at a time (notebook 05), its degrees of freedom a
  panel per kind by :mod:`toolkit.plots.dof_panels`, and a 3D scene as a still, its panels by
  :mod:`toolkit.plots.still_panels`;
- :mod:`toolkit.plots.reproduction` — the reproduction's figures (paper Figures 5-7, ``toolkit reproduce``);
- :mod:`toolkit.plots.crossover` — where prediction pays: exact and learned cost per configuration
  (``toolkit bench --crossover``; notebook 04);
- :mod:`toolkit.plots.race` — our planners against OMPL's, median time a query (``docs/planner_race.md``);
- :mod:`toolkit.plots.tutorials` — what only the tutorials show: a mesh workspace, samplers in a narrow passage.

Every figure's colours come from :mod:`toolkit.plots.palette` (told apart by colour-blind readers too) and
each figure carries a text alternative (:mod:`toolkit.plots.alt`; in a notebook, importing this package
makes every displayed figure carry it as its ``alt``).

>>> from toolkit.plots import reproduction  # doctest: +SKIP
"""

from toolkit.plots import alt
from toolkit.plots.crossover import crossover
from toolkit.plots.reproduction import (
    cae_reconstruction,
    planning_times,
    threshold_sweep,
)

__all__ = ["cae_reconstruction", "crossover", "planning_times", "threshold_sweep"]

alt.register()  # in a notebook: every figure displayed from now on has its alt text
