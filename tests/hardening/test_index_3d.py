"""The 3-D entry points index through the same validation path as the 2-D ones
(:func:`scanline._validate.index_array`): faces of meshes, edges of wireframes and
counts of 3-D polygon batches (issue 11, item 1)."""

import numpy as np
import pytest

import scanline as sl

V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
HOSTILE = [np.array([[0, 1, 2**64 - 1]], np.uint64), np.array([[0, 1, -1]]),
           np.array([[0, 1, 2.0]]), np.array([[0, 1, 4]]), np.array([[True, False, True]])]


@pytest.mark.parametrize("faces", HOSTILE, ids=["uint64-wrap", "negative", "float", "beyond",
                                                  "bool"])
def test_mesh_faces(faces):
    with pytest.raises(sl.ScanlineError, match=r"faces"):
        sl.mesh.Mesh(V, faces)
    with pytest.raises(sl.ScanlineError, match=r"faces\[0\]"):
        sl.mesh.Mesh(V, [faces[0].tolist() if faces.dtype != np.uint64 else faces[0]])


@pytest.mark.parametrize("edges", [np.array([[0, 2**64 - 1]], np.uint64), np.array([[0, -1]]),
                                   np.array([[0, 1.0]]), np.array([[0, 4]])])
def test_wireframe_edges(edges):
    cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
                    projection=sl.projection.perspective(fov=1.0, aspect=1.0, near=0.5, far=20))
    with pytest.raises(sl.ScanlineError, match="edges"):
        sl.draw3d.project_edges(V, edges, cam, 20, 20)


@pytest.mark.parametrize("counts", [np.array([2**63, 2**63, 4], np.uint64), [2**62] * 4 + [4],
                                    [4.0], [-1, 5], [1, 2]])
def test_polygons3d_counts(counts):
    with pytest.raises(sl.ScanlineError, match="counts"):
        sl.clip.polygons3d(V, sl.clip.box((-1, -1, -1), (2, 2, 2)), counts=counts)


def test_valid_faces_edges_and_counts_still_work():
    m = sl.mesh.Mesh(V, np.array([[0, 1, 2], [0, 1, 3]], np.uint8))
    assert m.face_indices.tolist() == [0, 1, 2, 0, 1, 3] and m.face_indices.dtype == np.int64
    pts, counts = sl.clip.polygons3d(V, sl.clip.box((-1, -1, -1), (2, 2, 2)), counts=[4])
    assert counts.tolist() == [4]
