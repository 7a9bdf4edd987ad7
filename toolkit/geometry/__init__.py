"""The geometry of the paper's problems (§II-B, §IV-A): robots, workspaces, and the exact answer to
"is this configuration in collision?". Everything else rests on it; it rests only on :mod:`toolkit.util`.

Reading order:

1. :mod:`toolkit.geometry.robots` — ``BoxRobot``: configurations, vectorized forward kinematics to
   oriented link boxes; the 2D point robot, the youBot-like 8-DoF, the 7- and 9-DoF box chains;
2. :mod:`toolkit.geometry.workspace` — ``Workspace``: a region with axis-aligned blocks, its −1/+1
   occupancy grid, the seeded generators of 2DS, 3DO and 3DC; ``from_mesh`` for a triangle mesh;
3. :mod:`toolkit.geometry.meshes` — triangle meshes as obstacles (fcl BVH, inside tests, voxels);
4. :mod:`toolkit.geometry.collision` — the checker interface (``are_valid(Q)``, clearance bounds)
   and the exact checkers: python-fcl for blocks and for meshes, a separating-axis reference, and
   interval tests in numpy for the point robot; ``exact_checker`` picks the fastest.
"""
