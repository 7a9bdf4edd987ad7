"""The paper's offline phase (§III-A, §IV-B): labelled data, the CAE and the MLP, and the learned
checker that puts them behind the same interface as the exact one. Rests on :mod:`toolkit.geometry`
and :mod:`toolkit.scenarios` only.

Reading order:

1. :mod:`toolkit.learning.data` — balanced labelled datasets, the seen / unseen splits (§IV-A);
2. :mod:`toolkit.learning.encoding` — what the MLP sees: ``[z, q]`` or ``[z, patch, pose]``;
3. :mod:`toolkit.learning.models` — the CAE (Eq. 1) and the collision MLP (§III-A);
4. :mod:`toolkit.learning.inference` — the MLP frozen in one workspace, for fast answers (§III-B line 3);
5. :mod:`toolkit.learning.presets` — the ``paper`` and ``strong`` recipes;
6. :mod:`toolkit.learning.training` — fitting and evaluating both networks;
7. :mod:`toolkit.learning.metrics` — accuracy, TPR, TNR (Tables 1-2);
8. :mod:`toolkit.learning.checkpoints` — a trained model as a folder;
9. :mod:`toolkit.learning.learned` — ``LearnedChecker``: the online phase's predictor (§III-B lines 1 and 3).
"""
