"""Which planner plans with a model: a training recipe (a preset) paired with planner settings.

A preset (:mod:`toolkit.learning.presets`) says how a model is trained; planner options
(:mod:`toolkit.planning.options`) say how a planner runs. Neither package knows the other, so the
experiments pair them, here:

- ``paper``: the paper's Algorithm 1 (``PRMOptions``, :mod:`toolkit.planning.paper_prm`), with and
  without its model; with it, every round after the first samples exactly (§III-B: "create additional
  valid samples using auxiliary samplers"). Its Table 3 compares what the paper compares.
- ``strong``: the lazy PRM (``LazyPRMOptions``), the best exact planner; with its model, learned edge
  screening and rounds that the exact checker confirms (the paper's future work).
- a recipe made from one of these (``dataclasses.replace(presets.get("strong"), name=...)``): as the
  one it was made from (``Preset.origin``);
- a recipe of your own: the lazy PRM, its model deciding samples only, unless you
  :func:`register` a pairing for it.

``toolkit.experiments.queries.planner_options(scenario, preset, predicted=...)`` builds the options
from a pairing, and ``default_options(scenario, learned)`` for a learned checker's preset.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from types import MappingProxyType

from toolkit.learning.presets import Preset
from toolkit.planning.options import LazyPRMOptions, PRMOptions
from toolkit.util import registry


@dataclass(frozen=True)
class Pairing:
    """How a recipe's model is planned with: the planner (its options' class), with and without the model, and the
    settings that apply only when the model decides samples. ``Pairing()``: the lazy PRM with its own defaults (what
    a predictor that is no recipe's model gets)."""

    options: type[PRMOptions] = LazyPRMOptions
    with_model: Mapping[str, object] = field(default_factory=lambda: MappingProxyType({}))


PAIRINGS: dict[str, Pairing] = {  # preset name -> pairing
    "paper": Pairing(PRMOptions, MappingProxyType({"auxiliary": "exact"})),
    "strong": Pairing(LazyPRMOptions, MappingProxyType({"screen_edges": True, "auxiliary": "confirmed"})),
}
OWN_RECIPE = Pairing(LazyPRMOptions, MappingProxyType({"screen_edges": False, "auxiliary": "exact"}))


def register(preset_name: str, pairing: Pairing, *, replace: bool = False) -> Pairing:
    """Plan with models of the preset ``preset_name`` as ``pairing`` says (``toolkit reproduce``, ``toolkit plan
    --predict``, the viewer). A name already paired is refused unless ``replace``; so is a pairing whose settings
    its planner does not read."""
    if not (isinstance(pairing.options, type) and issubclass(pairing.options, PRMOptions)):
        raise TypeError(f"a pairing's options are a planner's options class, got {pairing.options!r}")
    if unknown := sorted(set(pairing.with_model) - {f.name for f in fields(pairing.options)}):
        raise ValueError(f"{pairing.options.__name__} has no field(s) {unknown}")
    return registry.bind(PAIRINGS, preset_name, pairing, kind="planner pairing", replace=replace)


def pairing(preset: Preset) -> Pairing:
    """The pairing of ``preset``: by its name, else by the recipe it was made from (``Preset.origin``: a copy of
    ``strong`` with other sizes plans as ``strong`` does), else :data:`OWN_RECIPE`."""
    return PAIRINGS.get(preset.name) or PAIRINGS.get(preset.origin, OWN_RECIPE)
