"""Which planner a training recipe's experiments plan with: a preset paired with a planner by name.

A preset (:mod:`toolkit.learning.presets`) says how a model is trained; a planner
(:mod:`toolkit.planning.prm`: ``paper``, ``lazy``, one you register) says how a query is solved.
Neither package knows the other, so the experiments that train a recipe and plan with it
(``toolkit reproduce``, ``ablate``) pair them, here:

- ``paper``: the paper's Algorithm 1 (planner ``paper``, :mod:`toolkit.planning.paper_prm`): its
  Table 3 compares what the paper compares;
- ``strong``: the lazy PRM (planner ``lazy``), the best exact planner, with learned edge screening;
- a recipe made from one of these (``dataclasses.replace(presets.get("strong"), name=...)``): as the
  one it was made from (``Preset.origin``);
- a recipe of your own: the default planner (``toolkit.planning.prm.DEFAULT``) unless you
  :func:`register` a pairing for it.

A pairing holds for the recipe's runs with *and* without its model: "with / without prediction"
compares one planner with the same parameters, and only the checker differs. Elsewhere (``toolkit
plan``, ``bench``, the viewer, the notebooks) the caller names the planner; unnamed, it is
``toolkit.planning.prm.DEFAULT``, whatever checker decides samples.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from toolkit.learning.presets import Preset
from toolkit.planning import prm
from toolkit.planning.planner import replace_fields
from toolkit.util import registry


@dataclass(frozen=True)
class Pairing:
    """The planner a recipe's runs plan with, by name, and changes to its parameters (with and without the model
    alike). ``Pairing()``: the default planner with its own parameters."""

    planner: str = prm.DEFAULT
    params: Mapping[str, object] = field(default_factory=lambda: MappingProxyType({}))


PAIRINGS: dict[str, Pairing] = {  # preset name -> pairing
    "paper": Pairing("paper"),
    "strong": Pairing("lazy"),
}
OWN_RECIPE = Pairing()  # a recipe paired with nothing


def register(preset_name: str, pairing: Pairing, *, replace: bool = False) -> Pairing:
    """Plan the runs of the preset ``preset_name`` as ``pairing`` says (``toolkit reproduce``). A name already
    paired is refused unless ``replace``; so is an unknown planner, or a parameter its planner does not have."""
    replace_fields(prm.get(pairing.planner).Params(), pairing.params)  # a one-line error naming what is wrong
    return registry.bind(PAIRINGS, preset_name, pairing, kind="planner pairing", replace=replace)


def pairing(preset: Preset) -> Pairing:
    """The pairing of ``preset``: by its name, else by the recipe it was made from (``Preset.origin``: a copy of
    ``strong`` with other sizes plans as ``strong`` does), else :data:`OWN_RECIPE`."""
    return PAIRINGS.get(preset.name) or PAIRINGS.get(preset.origin, OWN_RECIPE)
