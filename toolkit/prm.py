"""``toolkit.prm``: PRM with and without prediction, kept at this name for code written against it; the code is in
:mod:`toolkit.planning.prm`."""

from toolkit.planning.prm import (
    AUXILIARY,
    GOAL,
    PAPER_BASELINE,
    STAGES,
    START,
    PlanResult,
    PlanStep,
    PRMOptions,
    plan,
)

__all__ = ["AUXILIARY", "GOAL", "PAPER_BASELINE", "STAGES", "START", "PRMOptions", "PlanResult", "PlanStep", "plan"]
