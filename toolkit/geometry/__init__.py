"""The geometry of the paper's problems (§II-B, §IV-A): robots, workspaces, and the exact answer to
"is this configuration in collision?". Everything else rests on it; it rests only on :mod:`toolkit.util`.

Reading order:

1. :mod:`toolkit.geometry.robots` — ``BoxRobot``: configurations, vectorized forward kinematics to
   oriented link boxes; the 2D point robot, the youBot-like 8-DoF, the 7- and 9-DoF box chains;
2. :mod:`toolkit.geometry.workspace` — ``Workspace``: a region with axis-aligned blocks, its −1/+1
   occupancy grid, the seeded generators of 2DS, 3DO and 3DC; ``from_mesh`` for a triangle mesh;
3. :mod:`toolkit.geometry.meshes` — triangle meshes as obstacles (fcl BVH, inside tests, voxels);
4. :mod:`toolkit.geometry.checker` — the checker interface: ``are_valid(Q)``, clearance bounds;
5. :mod:`toolkit.geometry.box_world` — what the box-world checkers share (a grid of cells listing the
   obstacles near each, clearance bounds), the numpy prefilter of the reference checkers, the point
   robot's interval tests and the separating-axis reference in numpy;
6. :mod:`toolkit.geometry.fcl_checker` — python-fcl: ``FCLChecker``, the reference, and
   ``MeshChecker`` for meshes;
7. :mod:`toolkit.geometry.compiled` and :mod:`toolkit.geometry.block_kernels` — ``CompiledChecker``:
   kinematics and separating axes compiled with numba, one loop over blocks of configurations, the default; its
   pieces (link bounds, separating axes, grid cells) in :mod:`toolkit.geometry.kernels`, its kinematics in
   :mod:`toolkit.geometry.frame_kernels`, their sines and cosines in :mod:`toolkit.geometry.trig`,
   the far bits that settle most links (built with the checker) in :mod:`toolkit.geometry.far_kernels`;
8. :mod:`toolkit.geometry.compiled_mesh` and :mod:`toolkit.geometry.mesh_kernels` — ``CompiledMeshChecker``:
   the same against a triangle mesh (triangle-box separating axes, inside tests from cells classified once);
9. :mod:`toolkit.geometry.collision` — all of them in one place, and ``exact_checker``, which picks the
   fastest from one table: compiled for box worlds and meshes, numpy for the point robot.
"""
