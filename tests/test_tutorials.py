"""Every tutorial (``tutorials/*.ipynb``) runs top to bottom in quick mode and is listed in ``tutorials/README.md``
with its measured running time (that it is committed without outputs: ``test_notebooks.py``).

Executed with nbclient in a real kernel from the tutorial's folder, as JupyterLab would
(a tutorial reads ``data/room.stl`` relative to itself); trained models go to a cache
folder of this test session.
"""

import re
from pathlib import Path

FOLDER = Path(__file__).resolve().parents[1] / "tutorials"
TUTORIALS = sorted(FOLDER.glob("*.ipynb"))  # assignments/ (otter masters) are tested with the grader, not here
EXPECTED = {
    "getting_started",
    "your_own_workspace",
    "add_a_sampler",
    "add_a_robot",
    "train_on_your_data",
    "plan_with_ompl",
}


def test_the_six_tutorials_exist_and_the_readme_lists_each_with_a_time():
    assert {p.stem for p in TUTORIALS} == EXPECTED
    readme = (FOLDER / "README.md").read_text()
    for path in TUTORIALS:
        row = next((line for line in readme.splitlines() if f"({path.name})" in line), None)
        assert row is not None, f"tutorials/README.md does not link {path.name}"
        assert re.search(r"\d+\s*(s|min)\b", row), f"tutorials/README.md gives no running time for {path.name}: {row}"


# Running each one in quick mode (no error, its figures shown) is tests/test_site.py's build: one execution serves both.
