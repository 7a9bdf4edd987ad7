"""The library's shape, held as it is promised in the packages' docstrings and docs/design.md.

Packages are layers (``LAYERS``): a module imports only from lower layers and its own
package, ``learning`` and ``planning`` never import each other, and no two modules import
each other, even indirectly (imports inside functions count). Lower layers know nothing of
higher ones' settings: no planner vocabulary in ``geometry`` or ``learning``. No module only
re-exports names of another. Modules stay under 400 lines,
functions under 60, and no module imports another's private name.
"""

import ast
import dataclasses
import re
from pathlib import Path

import pytest

from toolkit.planning import prm

ROOT = Path(__file__).resolve().parents[1] / "toolkit"
LAYERS = {  # package (or top-level module) -> layer; a module imports only from lower layers and its own package
    "util": 0,
    "geometry": 1,
    "scenarios": 2,
    "learning": 3,
    "planning": 3,
    "plots": 4,
    "experiments": 5,
    "viewer": 6,
    "teaching": 7,
    "cli": 8,
    "__main__": 9,
}
MAX_MODULE_LINES = 400
MAX_FUNCTION_LINES = 60


def modules() -> dict[str, Path]:
    return {
        ".".join(p.relative_to(ROOT.parent).with_suffix("").parts).removesuffix(".__init__"): p
        for p in sorted(ROOT.rglob("*.py"))
    }


def imports(path: Path) -> list[tuple[str, list[str], int]]:
    """``(module, names, line)`` of every toolkit import in the file, those inside functions included."""
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.split(".")[0] == "toolkit":
            found.append((node.module, [a.name for a in node.names], node.lineno))
        elif isinstance(node, ast.Import):
            found += [(a.name, [], node.lineno) for a in node.names if a.name.split(".")[0] == "toolkit"]
    return found


def targets(module: str, names: list[str], known: dict[str, Path]) -> list[str]:
    """The toolkit modules an import statement loads: ``from toolkit.x import y`` is ``toolkit.x.y`` when that is a
    module, else ``toolkit.x``."""
    found = [f"{module}.{name}" for name in names if f"{module}.{name}" in known]
    return found or [module]


def part(module: str) -> str:
    """The layer key of a module: its package below ``toolkit`` (or its own name at the top)."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "toolkit"


def test_every_package_has_a_layer():
    assert {part(m) for m in modules()} - {"toolkit"} <= set(LAYERS)


def test_modules_import_only_lower_layers_and_their_own_package():
    known, wrong = modules(), []
    for name, path in known.items():
        if name == "toolkit":
            continue
        mine = part(name)
        for module, names, line in imports(path):
            for target in targets(module, names, known):
                theirs = part(target)
                if theirs == "toolkit" or theirs == mine:
                    continue
                if LAYERS[theirs] >= LAYERS[mine] and not (mine == "__main__" and theirs == "cli"):
                    wrong.append(
                        f"{path.relative_to(ROOT.parent)}:{line} ({mine}, layer {LAYERS[mine]}) imports "
                        f"{target} (layer {LAYERS[theirs]})"
                    )
    assert wrong == []


def test_no_import_cycles():
    known = modules()
    graph = {
        name: {
            t for module, names, _ in imports(path) for t in targets(module, names, known) if t in known and t != name
        }
        for name, path in known.items()
    }
    for package in [m for m in known if known[m].name == "__init__.py"]:  # a package's __init__ may re-export its own
        graph[package] = {t for t in graph[package] if not t.startswith(package + ".")}
    cycles, state = [], {}

    def visit(node, stack):
        state[node] = "open"
        for nxt in graph[node]:
            if state.get(nxt) == "open":
                cycles.append(stack[stack.index(nxt) :] + [nxt])
            elif nxt not in state:
                visit(nxt, stack + [nxt])
        state[node] = "done"

    for name in graph:
        if name not in state:
            visit(name, [name])
    assert cycles == []


def test_modules_and_functions_stay_short():
    long = []
    for name, path in modules().items():
        text = path.read_text()
        if len(text.splitlines()) > MAX_MODULE_LINES:
            long.append(f"{name}: {len(text.splitlines())} lines")
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                length = node.end_lineno - node.lineno + 1
                if length > MAX_FUNCTION_LINES:
                    long.append(f"{name}.{node.name}: {length} lines")
    assert long == []


def test_no_module_imports_another_modules_private_names():
    private = [
        f"{name}: {module}.{n}"
        for name, path in modules().items()
        for module, names, _ in imports(path)
        for n in names
        if n.startswith("_") and not n.startswith("__")
    ]
    assert private == []


def private_names(tree: ast.Module) -> set[str]:
    """The private names (``_x``, not ``__x__``) a module defines: its functions, classes and methods, the names it
    assigns and the attributes it sets (``self._x = ...``)."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            found.add(node.name)
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
            found.add(node.attr)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            found.add(node.id)
    return {name for name in found if name.startswith("_") and not name.endswith("__")}


def private_reads(sources: dict[str, str]) -> list[str]:
    """``module:line: thing._x`` wherever a module of ``sources`` (name -> code) reads an attribute ``_x`` that another
    of them defines and it does not."""
    trees = {name: ast.parse(code) for name, code in sources.items()}
    defined = {name: private_names(tree) for name, tree in trees.items()}
    anyone = set().union(*defined.values())
    return [
        f"{name}:{node.lineno}: {ast.unparse(node.value)}.{node.attr}"
        for name, tree in trees.items()
        for node in ast.walk(tree)
        if isinstance(node, ast.Attribute) and node.attr in anyone - defined[name]
    ]


def test_no_module_reads_another_modules_private_attributes():
    """Issue 48: ``thing._x`` (``self._x`` too) where ``_x`` is private to another toolkit module (it defines it,
    this module does not): a function that reads a checker's ``_shape`` from another module, a subclass that
    reads its base's private state, a module that calls ``other_module._helper``. They ask for a public, documented
    accessor instead. (Underscored names that no toolkit module defines, ``os._exit`` or a NamedTuple's
    ``_replace``, are the libraries' business.)"""
    assert private_reads({name: path.read_text() for name, path in modules().items()}) == []


def test_the_private_attribute_check_sees_a_read_across_modules():
    """The check above on made-up modules: another's private attribute read is found, one's own is not."""
    grid = "class Grid:\n    def __init__(self):\n        self._shape = (3, 3)\n        self.shape = self._shape\n"
    arrays = "def arrays(grid):\n    return grid._shape, grid.shape\n"
    assert private_reads({"grid": grid, "arrays": arrays}) == ["arrays:2: grid._shape"]
    assert private_reads({"grid": grid, "arrays": arrays.replace("grid._shape", "grid.shape")}) == []


PLANNER_WORDS = (
    "PaperParams",
    "LazyParams",
    "RoadmapParams",
    "make_planner",
    "screen_edges",
    "auxiliary",
    "exact_every",
    "lazy PRM",
)


@pytest.mark.parametrize("package", ["geometry", "learning"])
def test_lower_layers_know_no_planner_settings(package):
    """What a checker or a model *is* may live below planning; how a planner uses it lives in planning and in the
    experiments that pair a model with a planner."""
    found = [
        f"{path.relative_to(ROOT.parent)}:{n}: {word}"
        for path in sorted((ROOT / package).rglob("*.py"))
        for n, line in enumerate(path.read_text().splitlines(), 1)
        for word in PLANNER_WORDS
        if word in line
    ]
    assert found == []


def test_no_module_only_re_exports_names():
    """A module that only imports names (and lists them in ``__all__``) is an old name kept alive: use the new one.
    (A package's ``__init__`` may gather the names a user starts with, as ``toolkit.viewer`` does.)"""
    only_imports = []
    for name, path in modules().items():
        if path.name == "__init__.py":
            continue
        body = ast.parse(path.read_text()).body
        statements = [s for s in body if not (isinstance(s, ast.Expr) and isinstance(s.value, ast.Constant))]
        imported = [s for s in statements if isinstance(s, (ast.Import, ast.ImportFrom))]
        if imported and all(
            isinstance(s, (ast.Import, ast.ImportFrom))
            or (isinstance(s, ast.Assign) and any(getattr(t, "id", "") == "__all__" for t in s.targets))
            or (isinstance(s, ast.ImportFrom) and s.module == "__future__")
            for s in statements
        ):
            only_imports.append(name)
    assert only_imports == []


COURSE_BUILD = ("mkdocs", "nbconvert", "nbclient", "playwright")  # mkdocs also stands for its plugins: mkdocs_*, ...
LAZY_COURSE_BUILD = {("toolkit.viewer.browser", "playwright")}  # `toolkit view --screenshot`, imported when it runs


def test_the_library_imports_no_course_build_tool():
    """mkdocs (and its plugins), nbconvert, nbclient and Playwright build the course (``tools/``, not installed) and
    come with the dev extras only: no module of ``toolkit`` imports them, imports inside functions included. The one
    exception (``LAZY_COURSE_BUILD``) imports Playwright inside the function that needs it, never at module level:
    ``toolkit view --screenshot`` drives Chromium with it and says what to install when it is missing."""
    found = []
    for name, path in modules().items():
        tree = ast.parse(path.read_text())
        in_functions = {
            id(inner)
            for node in ast.walk(tree)
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
            for inner in ast.walk(node)
        }
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                roots = [alias.name.split(".")[0] for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                roots = [node.module.split(".")[0]]
            else:
                continue
            for root in roots:
                tool = next((t for t in COURSE_BUILD if root == t or root.startswith(t)), None)
                if tool is None or ((name, tool) in LAZY_COURSE_BUILD and id(node) in in_functions):
                    continue
                found.append(f"{path.relative_to(ROOT.parent)}:{node.lineno} imports {root}")
    assert found == []


def test_each_planner_owns_frozen_parameters_and_the_default_is_named_once():
    """Issue 48: a planner's parameters are a frozen dataclass of its own, no planner's a subclass of another's; the
    planner that runs when none is named is written in one place, ``prm.DEFAULT`` (a planner's own ``name`` and a
    recipe's pairing name planners too; nothing else under ``toolkit/`` writes a planner's name as a default)."""
    for name in prm.names():
        params = prm.get(name).Params
        assert dataclasses.is_dataclass(params) and params.__dataclass_params__.frozen
        assert not any(issubclass(params, prm.get(other).Params) for other in prm.names() if other != name)
    allowed = {"planning/prm.py", "planning/lazy_prm.py", "experiments/planners.py"}
    named = [
        f"{path.relative_to(ROOT)}:{n}"
        for path in sorted(ROOT.rglob("*.py"))
        for n, line in enumerate(path.read_text().splitlines(), 1)
        if re.search(r"""["']lazy["']""", line) and str(path.relative_to(ROOT)) not in allowed
    ]
    assert named == []
