"""``toolkit.workspace``: workspaces, their occupancy grids and generators, kept at this name for
code written against it; the code is in :mod:`toolkit.geometry.workspace`."""

from toolkit.geometry.workspace import (
    GENERATORS,
    MeshWorkspace,
    Workspace,
    clutter_3d,
    from_mesh,
    generate,
    office_3d,
    simple_2d,
)

__all__ = ["GENERATORS", "MeshWorkspace", "Workspace", "clutter_3d", "from_mesh", "generate", "office_3d", "simple_2d"]
