"""The autograder zip carries the toolkit, so that Gradescope installs it from the zip, not from an index.

``otter assign`` writes a zip whose ``setup.sh`` builds the grading image (on Gradescope) from the
zip's ``environment.yml``, whose pip part names the packages to install. This toolkit is on no
package index, so :func:`ship_toolkit` puts it in the zip as a wheel built from this working tree
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

ROOT = Path(__file__).resolve().parents[2]  # the repository: pyproject.toml, README.md and toolkit/ build the wheel
TORCH_INDEX = "https://download.pytorch.org/whl/cpu"  # torch's CPU builds (as in binder/requirements.txt)


def torch_pin() -> str:
    """The CPU build of the torch version ``constraints.txt`` pins, e.g. ``torch==2.13.0+cpu``."""
    pins = [line.strip() for line in (ROOT / "constraints.txt").read_text().splitlines()]
    return next(f"{pin}+cpu" for pin in pins if pin.startswith("torch=="))


def build_wheel(out: Path) -> Path:
    """A wheel of the toolkit alone (no dependencies) built from a copy of this working tree, written into ``out``
    (a copy: setuptools would leave a ``build/`` folder in the tree, and stale modules in later wheels)."""
    with tempfile.TemporaryDirectory() as tree:
        for name in ("pyproject.toml", "README.md", "LICENSE"):
            shutil.copy(ROOT / name, tree)
        shutil.copytree(ROOT / "toolkit", Path(tree, "toolkit"), ignore=shutil.ignore_patterns("__pycache__"))
        wheel = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "--wheel-dir", str(out), tree]
        done = subprocess.run(wheel, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"could not build the toolkit's wheel:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")
    return next(Path(out).glob("sample_collision_toolkit-*.whl"))


def requirements(wheel: str) -> list[str]:
    """The pip lines that install the toolkit from ``wheel`` (its path on the grading machine) with the CPU torch."""
    return [f"--extra-index-url {TORCH_INDEX}", torch_pin(), wheel]


def ship_toolkit(zip_path: Path) -> None:
    """Add the toolkit's wheel to the autograder zip ``zip_path`` (at its root, which Gradescope unpacks into
    ``<autograder_dir>/source``) and its :func:`requirements` to the zip's ``environment.yml``, as otter writes it
    for a ``requirements:`` and a ``python_version:`` in the assignment's config."""
    from otter.generate import CondaEnvironment  # otter: the dev extra, which builds assignments
    from otter.run import AutograderConfig

    with tempfile.TemporaryDirectory() as work:
        wheel = build_wheel(Path(work))
        shipped = Path(work, zip_path.name)
        with zipfile.ZipFile(zip_path) as built, zipfile.ZipFile(shipped, "w", zipfile.ZIP_DEFLATED) as new:
            config = AutograderConfig(json.loads(built.read("otter_config.json")))
            python = "{}.{}".format(*sys.version_info[:2])
            pip = requirements(f"{config.autograder_dir}/source/{wheel.name}")
            environment = CondaEnvironment(python, False, pip, False, None).to_str()
            for item in built.infolist():
                new.writestr(item, environment if item.filename == "environment.yml" else built.read(item))
            new.write(wheel, wheel.name)
        shutil.move(shipped, zip_path)
