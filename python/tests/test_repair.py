"""msmesh.repair (docs/robustness.md "Repair")."""

import numpy as np
import pytest

import msmesh


def tetrahedron():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return V, F


def test_repair_fixes_duplicates_degenerate_faces_and_orientation():
    V, F = tetrahedron()
    V = np.vstack([V, V[1]])                     # vertex 4 duplicates vertex 1
    F = np.vstack([F, F[0], [0, 1, 1]])          # a duplicate face and one repeating a vertex
    F[3] = F[3][[0, 2, 1]]                       # one face flipped
    F[1] = [0, 4, 3]                             # uses the duplicate vertex
    r = msmesh.repair(V, F)
    rep = r["report"]
    assert rep["merged_vertices"] == 1
    assert rep["duplicate_faces_removed"] == 1
    assert rep["degenerate_faces_removed"] == 1
    assert rep["flipped_faces"] == 1
    assert rep["changed"] and len(rep["actions"]) == 4
    assert r["F"].shape == (4, 3) and r["V"].shape == (5, 3)       # vertex order kept
    assert list(r["face_origin"]) == [0, 1, 2, 3]
    np.testing.assert_array_equal(r["F"], tetrahedron()[1])
    # Removing unreferenced vertices renumbers: the copy goes.
    r2 = msmesh.repair(V, F, remove_unreferenced=True)
    assert r2["V"].shape == (4, 3)
    assert list(r2["vertex_map"]) == [0, 1, 2, 3, -1]


def test_repair_splits_a_non_manifold_edge():
    V = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1, 0.2], [0.5, 0, 1]], dtype=float)
    F = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    r = msmesh.repair(V, F, split_non_manifold=True)
    assert r["report"]["split_vertices"] == 4
    assert r["report"]["non_manifold_edges"] == 0 and r["report"]["non_manifold_vertices"] == 0
    assert r["V"].shape == (9, 3)
    np.testing.assert_array_equal(r["V"][:5], V)


def test_repair_rejects_bad_input_and_parameters():
    V, F = tetrahedron()
    with pytest.raises(msmesh.InvalidInputError, match="weld"):
        msmesh.repair(V, F, weld=-1)
    with pytest.raises(msmesh.InvalidInputError, match=r"\[0, 1\]"):
        msmesh.repair(V, F, weld=5)
    V2 = V.copy()
    V2[1, 0] = np.nan
    with pytest.raises(msmesh.InvalidInputError, match="not finite"):
        msmesh.repair(V2, F)
