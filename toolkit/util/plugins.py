"""Your own code in the ``toolkit`` command: modules that register a sampler, a preset or a scenario.

``toolkit plan --import my_samplers --sampler MA`` imports ``my_samplers`` (a module on
the Python path or in the current folder, or a ``.py`` file) before the command reads
its choices, so that what the module registers (``register_sampler``,
``presets.register``, ``scenarios.register``) is offered like the toolkit's own.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
from pathlib import Path
from types import ModuleType


def import_module(name: str) -> ModuleType:
    """Import ``name``: a dotted module name (the current folder is searched too, as ``python -m`` does) or a path
    to a ``.py`` file; an error that says which, and why, when it cannot be imported."""
    path = Path(name)
    if path.suffix == ".py":
        if not path.is_file():
            raise ValueError(f"--import {name}: no such file")
        spec = importlib.util.spec_from_file_location(path.stem, path)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules[path.stem] = module
        spec.loader.exec_module(module)
        return module
    if "" not in sys.path and str(Path.cwd()) not in sys.path:
        sys.path.insert(0, str(Path.cwd()))
    try:
        return importlib.import_module(name)
    except ImportError as err:
        raise ValueError(f"--import {name}: {err}") from None
