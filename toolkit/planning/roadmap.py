"""A probabilistic roadmap: nodes, edges, k-nearest candidates and shortest paths (Kavraki et al. 1996).

Distances are ``||w * difference(q0, q1)||`` with ``w = robot.motion_weights``: a
rotation counts by how far it can move the robot, and angles wrap around. The
k-nearest search is a ``scipy.spatial.cKDTree`` on the scaled configurations with a
periodic box along the angle axes (``boxsize``), so it is exact under that metric.

Every node remembers whether the exact checker has confirmed it (``node_verified``),
every edge the finest resolution at which it did (``edge_checked_at``, ``inf``: not
yet) and, when screened by prediction, where along it prediction saw it fail
(``edge_suspect``, a fraction from ``edges[:, 0]``; NaN: nowhere); the planner
(:mod:`toolkit.planning.query_roadmap`) confirms a path's nodes and edges before it
returns it. Pairs that were decided against (``reject``, and every removed edge) are remembered in ``rejected``
and never offered again, so bridging a split roadmap tries new pairs each time.
"""

from __future__ import annotations

import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import connected_components, dijkstra
from scipy.spatial import cKDTree

from toolkit.geometry.robots import BoxRobot


class Roadmap:
    """``nodes (V, dof)``, ``edges (E, 2)`` int (i < j), ``edge_cost (E,)``, ``node_verified (V,)``,
    ``edge_checked_at (E,)``, ``edge_suspect (E,)``, ``rejected (R, 2)`` int (i < j)."""

    def __init__(self, robot: BoxRobot):
        self.robot = robot
        self.nodes = np.zeros((0, robot.dof))
        self.node_verified = np.zeros(0, dtype=bool)
        self.edges = np.zeros((0, 2), dtype=int)
        self.edge_cost = np.zeros(0)
        self.edge_checked_at = np.zeros(0)  # the finest resolution the exact checker confirmed each edge at
        self.edge_suspect = np.zeros(0)  # where along each edge screening predicted a collision (NaN: nowhere)
        self.rejected = np.zeros((0, 2), dtype=int)  # pairs decided against: never candidates again
        self._box = np.where(robot.wraps, 2 * np.pi * robot.motion_weights, 0.0)  # (dof,) period per axis, 0: none

    def __repr__(self) -> str:
        return f"Roadmap({len(self.nodes)} nodes, {len(self.edges)} edges)"

    def distance(self, Q0, Q1) -> np.ndarray:
        """``(N,)`` weighted distance with angles the short way round."""
        return np.linalg.norm(self.robot.difference(Q0, Q1) * self.robot.motion_weights, axis=-1)

    def add_nodes(self, Q: np.ndarray, verified: bool) -> np.ndarray:
        """Append ``Q (N, dof)``; returns their indices ``(N,)``."""
        first = len(self.nodes)
        self.nodes = np.concatenate([self.nodes, Q])
        self.node_verified = np.concatenate([self.node_verified, np.full(len(Q), verified)])
        return np.arange(first, len(self.nodes))

    def _scaled(self) -> np.ndarray:
        """``(V, dof)`` nodes scaled by the motion weights, angles shifted into ``[0, boxsize)`` for the KD-tree."""
        scaled = self.nodes * self.robot.motion_weights  # (V, dof)
        periodic = self._box > 0
        shifted = np.mod(scaled[:, periodic] + np.pi * self.robot.motion_weights[periodic], self._box[periodic])
        scaled[:, periodic] = np.where(shifted >= self._box[periodic], 0.0, shifted)
        return scaled

    def candidate_edges(self, new: np.ndarray, k: int) -> np.ndarray:
        """``(C, 2)`` pairs ``i < j``: each node of ``new`` with its ``k`` nearest other nodes, no duplicates."""
        if len(self.nodes) < 2 or len(new) == 0:
            return np.zeros((0, 2), dtype=int)
        scaled = self._scaled()
        count = min(k + 1, len(self.nodes))
        _, near = cKDTree(scaled, boxsize=self._box).query(scaled[new], k=count)  # (N, count), nearest first
        pairs = np.stack(np.broadcast_arrays(new[:, None], near.reshape(len(new), count)), axis=-1).reshape(-1, 2)
        pairs = np.unique(np.sort(pairs[pairs[:, 0] != pairs[:, 1]], axis=1), axis=0).reshape(-1, 2)  # no self-loops
        return pairs[self._untried(pairs)]  # nor edges already present, nor rejected pairs

    def bridge_edges(self, node: int, k: int) -> np.ndarray:
        """``(C, 2)``: up to ``k`` pairs joining ``node``'s connected component to the rest of the roadmap, closest
        first.

        k-nearest graphs of clustered samples (OB, G, BT gather around obstacles) fall
        apart into one component per cluster; trying the closest pairs between the
        query's component and the others joins them (a connected-component
        connection strategy, as in Morales et al.'s PRM toolkit, restricted to the query).
        Each of ``k`` members of the component offers its nearest outside node among
        the pairs not yet tried (of its ``k`` nearest), so a second call after the first
        pairs were rejected tries the next ones.
        """
        inside = self.component(node)
        if inside.all():
            return np.zeros((0, 2), dtype=int)
        scaled, outside, members = self._scaled(), np.flatnonzero(~inside), np.flatnonzero(inside)
        count = min(k, len(outside))
        gap, nearest = cKDTree(scaled[outside], boxsize=self._box).query(scaled[members], k=count)
        gap, nearest = gap.reshape(len(members), count), outside[nearest.reshape(len(members), count)]  # (M, count)
        pairs = np.stack(np.broadcast_arrays(members[:, None], nearest), axis=-1)  # (M, count, 2)
        gap[~self._untried(pairs.reshape(-1, 2)).reshape(gap.shape)] = np.inf
        first = gap.argmin(axis=1)  # (M,) each member's nearest untried pair (gaps ascend along a row)
        gap, pairs = gap[np.arange(len(members)), first], pairs[np.arange(len(members)), first]  # (M,), (M, 2)
        best = np.argsort(gap, kind="stable")[:k]
        return np.sort(pairs[best[np.isfinite(gap[best])]], axis=1)

    def component(self, node: int) -> np.ndarray:
        """``(V,)`` bool: the nodes connected to ``node``."""
        v = len(self.nodes)
        graph = csr_matrix((np.ones(len(self.edges)), (self.edges[:, 0], self.edges[:, 1])), shape=(v, v))
        _, label = connected_components(graph, directed=False)
        return label == label[node]

    def _untried(self, pairs: np.ndarray) -> np.ndarray:
        """``(C,)`` bool: the pairs ``(C, 2)`` (either order) that are neither an edge nor rejected."""
        v = len(self.nodes)
        tried = np.concatenate([self.edges, self.rejected]) @ [v, 1]
        return ~np.isin(np.sort(pairs, axis=1) @ [v, 1], tried)

    def reject(self, pairs: np.ndarray) -> None:
        """Remember pairs ``(C, 2)`` (i < j) decided against, so that no candidate offers them again."""
        self.rejected = np.concatenate([self.rejected, pairs])

    def add_edges(
        self, pairs: np.ndarray, cost: np.ndarray, checked_at: float = np.inf, suspect: np.ndarray | None = None
    ) -> None:
        """Append edges ``pairs (C, 2)`` of ``cost (C,)``, confirmed by the exact checker at ``checked_at`` (inf: not),
        with ``suspect (C,)`` where screening saw them fail (None: nowhere)."""
        self.edges = np.concatenate([self.edges, pairs])
        self.edge_cost = np.concatenate([self.edge_cost, cost])
        self.edge_checked_at = np.concatenate([self.edge_checked_at, np.full(len(pairs), float(checked_at))])
        self.edge_suspect = np.concatenate(
            [self.edge_suspect, np.full(len(pairs), np.nan) if suspect is None else suspect]
        )

    def remove_edges(self, which: np.ndarray) -> None:
        """Drop the edges selected by ``which`` (indices or a boolean mask) and remember them as rejected."""
        keep = np.ones(len(self.edges), dtype=bool)
        keep[which] = False
        self.reject(self.edges[~keep])
        self._keep_edges(keep)

    def _keep_edges(self, keep: np.ndarray) -> None:
        self.edges, self.edge_cost = self.edges[keep], self.edge_cost[keep]
        self.edge_checked_at, self.edge_suspect = self.edge_checked_at[keep], self.edge_suspect[keep]

    def remove_nodes(self, which: np.ndarray) -> None:
        """Drop nodes ``which`` (indices), their edges and rejected pairs; later nodes shift down (earlier ones keep
        their index)."""
        keep = np.ones(len(self.nodes), dtype=bool)
        keep[which] = False
        self._keep_edges(np.all(keep[self.edges], axis=1))
        self.rejected = self.rejected[keep[self.rejected].all(axis=1)]
        new_index = np.cumsum(keep) - 1  # (V,) old index -> new index for kept nodes
        self.edges, self.rejected = new_index[self.edges], new_index[self.rejected]
        self.nodes, self.node_verified = self.nodes[keep], self.node_verified[keep]

    def shortest_path(self, source: int, target: int) -> np.ndarray | None:
        """Node indices ``(P,)`` of the cheapest path (Dijkstra on ``edge_cost``), or None when disconnected."""
        v = len(self.nodes)
        cost = np.maximum(self.edge_cost, 1e-12)  # sparse graphs treat 0 as "no edge"
        graph = csr_matrix((cost, (self.edges[:, 0], self.edges[:, 1])), shape=(v, v))
        _, previous = dijkstra(graph, directed=False, indices=source, return_predecessors=True)
        if source != target and previous[target] < 0:
            return None
        path = [target]
        while path[-1] != source:
            path.append(previous[path[-1]])
        return np.array(path[::-1])

    def edge_index(self, path: np.ndarray) -> np.ndarray:
        """``(P-1,)`` index into ``edges`` of each step of a node path."""
        v = len(self.nodes)
        keys = self.edges @ [v, 1]  # (E,) unique: edges are i < j pairs without duplicates
        wanted = np.sort(np.stack([path[:-1], path[1:]], axis=1), axis=1) @ [v, 1]  # (P-1,)
        if not np.isin(wanted, keys).all():
            raise ValueError("the path takes a step that is not an edge of the roadmap")
        order = np.argsort(keys)
        return order[np.searchsorted(keys, wanted, sorter=order)]
