"""Teaching toolkit for *Predicting Sample Collision with Neural Networks* (Tran, Denny, Ekenna).

Modules, in the order a reader meets them: :mod:`~toolkit.workspace`,
:mod:`~toolkit.geometry.robots`, :mod:`~toolkit.scenarios`, :mod:`~toolkit.collision`,
:mod:`~toolkit.learning.data`, then learning, sampling and planning.
"""

__version__ = "0.1.0"
