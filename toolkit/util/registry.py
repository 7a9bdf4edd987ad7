"""Named registries: how a sampler, a preset or a scenario of yours joins the toolkit's own.

The toolkit keeps its samplers, presets and scenarios in dictionaries by name, and
reads them — never a list written out — wherever a name is offered (the command line,
the viewer, ``reproduce``). :func:`bind` adds to such a dictionary, refusing to rebind
a name by accident; :func:`lookup` reads it, with an error that lists the choices.
"""

from __future__ import annotations

from typing import TypeVar

T = TypeVar("T")


def bind(registry: dict[str, T], name: str, item: T, *, kind: str, replace: bool = False) -> T:
    """``registry[name] = item``; a name already bound to another item is refused unless ``replace``."""
    if not (isinstance(name, str) and name.strip()):
        raise ValueError(f"a {kind}'s name must be a non-empty string, got {name!r}")
    if name in registry and registry[name] is not item and not replace:
        raise ValueError(f"a {kind} called {name!r} exists; pass replace=True to rebind it")
    registry[name] = item
    return item


def lookup(registry: dict[str, T], name: str, *, kind: str) -> T:
    """``registry[name]``, or a ``ValueError`` that names the unknown ``kind`` and the registered choices."""
    try:
        return registry[name]
    except KeyError:
        raise ValueError(f"unknown {kind} {name!r}; choose one of {sorted(registry)}") from None
