"""The autograder zip carries the toolkit, so that Gradescope installs it from the zip, not from an index.

``otter assign`` writes a zip whose ``setup.sh`` builds the grading image (on Gradescope) from the
zip's ``environment.yml``, whose pip part names the packages to install. This toolkit is on no
package index, so :func:`ship_toolkit` puts it in the zip as a wheel built from the course's
repository or handout (passed in: the toolkit's source, ``pyproject.toml``, ``constraints.txt``)
and lists it there, beside torch's CPU build (the version pinned in ``constraints.txt``, from
PyTorch's CPU index; the default Linux wheel is the CUDA one, gigabytes more), in an environment of
the Python the wheel was built with. Grading (``run_autograder``, or ``otter run -a <zip>`` where
those packages are installed) then needs no network. Nothing else is added: the zip holds otter's
files and hidden tests, and the library, never a master's solutions.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

TORCH_INDEX = "https://download.pytorch.org/whl/cpu"  # torch's CPU builds (as in binder/requirements.txt)
SOURCE = ("pyproject.toml", "README.md", "LICENSE", "constraints.txt", "toolkit")  # what building the wheel reads


def torch_pin(source: Path) -> str:
    """The CPU build of the torch version ``source``'s ``constraints.txt`` pins, e.g. ``torch==2.13.0+cpu``."""
    pins = [line.strip() for line in (checked_source(source) / "constraints.txt").read_text().splitlines()]
    return next(f"{pin}+cpu" for pin in pins if pin.startswith("torch=="))


def checked_source(source: Path) -> Path:
    """``source`` when it holds the toolkit's source (what the wheel is built from); else a clear error."""
    missing = [name for name in SOURCE if not (Path(source) / name).exists()]
    if missing:
        raise FileNotFoundError(
            f"{source} lacks {', '.join(missing)}: an autograder carries a wheel of the toolkit built from the "
            "course's repository or handout; build the assignments there (make assignments)"
        )
    return Path(source)


def build_wheel(out: Path, source: Path) -> Path:
    """A wheel of the toolkit alone (no dependencies) built from a copy of ``source``, written into ``out``
    (a copy: setuptools would leave a ``build/`` folder in the tree, and stale modules in later wheels)."""
    source = checked_source(source)
    with tempfile.TemporaryDirectory() as tree:
        for name in ("pyproject.toml", "README.md", "LICENSE"):
            shutil.copy(source / name, tree)
        shutil.copytree(source / "toolkit", Path(tree, "toolkit"), ignore=shutil.ignore_patterns("__pycache__"))
        wheel = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "--wheel-dir", str(out), tree]
        done = subprocess.run(wheel, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"could not build the toolkit's wheel:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")
    return next(Path(out).glob("sample_collision_toolkit-*.whl"))


def requirements(wheel: str, source: Path) -> list[str]:
    """The pip lines that install the toolkit from ``wheel`` (its path on the grading machine) with the CPU torch."""
    return [f"--extra-index-url {TORCH_INDEX}", torch_pin(source), wheel]


def ship_toolkit(zip_path: Path, source: Path) -> None:
    """Add the toolkit's wheel, built from ``source`` (:func:`build_wheel`), to the autograder zip ``zip_path`` (at its
    root, which Gradescope unpacks into ``<autograder_dir>/source``) and its :func:`requirements` to the zip's
    ``environment.yml``, as otter writes it for a ``requirements:`` and a ``python_version:`` in the assignment's
    config."""
    from otter.generate import CondaEnvironment  # otter: the grading extra, which builds assignments
    from otter.run import AutograderConfig

    with tempfile.TemporaryDirectory() as work:
        wheel = build_wheel(Path(work), source)
        shipped = Path(work, zip_path.name)
        with zipfile.ZipFile(zip_path) as built, zipfile.ZipFile(shipped, "w", zipfile.ZIP_DEFLATED) as new:
            config = AutograderConfig(json.loads(built.read("otter_config.json")))
            python = "{}.{}".format(*sys.version_info[:2])
            pip = requirements(f"{config.autograder_dir}/source/{wheel.name}", source)
            environment = CondaEnvironment(python, False, pip, False, None).to_str()
            for item in built.infolist():
                new.writestr(item, environment if item.filename == "environment.yml" else built.read(item))
            new.write(wheel, wheel.name)
        shutil.move(shipped, zip_path)
