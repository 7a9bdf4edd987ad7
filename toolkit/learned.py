"""``toolkit.learned``: the learned checker, kept at this name for code written against it; the code is in
:mod:`toolkit.learning.learned`."""

from toolkit.learning.learned import LearnedChecker, load_checker

__all__ = ["LearnedChecker", "load_checker"]
