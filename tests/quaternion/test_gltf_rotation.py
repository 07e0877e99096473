"""glTF node rotations go through Quaternion: a rotated node reads as scipy rotates it,
and a zero rotation quaternion is refused naming the node."""

import numpy as np
import pytest

from scanline.mesh import MeshFileError, load
from tests.three_d.test_mesh_files_gltf import SQUARE, broken

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation


def test_a_node_rotation_reads_as_scipy_rotates(tmp_path):
    r = Rotation.from_rotvec([0.3, -1.1, 0.7])

    def rotate(doc):
        doc["nodes"][1].update(rotation=r.as_quat().tolist(), scale=[1, 1, 1])

    mesh = load(broken(tmp_path, rotate))
    expected = r.apply(SQUARE.astype(float)) + (10, 0, 0)
    got = mesh.vertices
    assert sorted(map(tuple, np.round(got, 5))) == sorted(map(tuple, np.round(expected, 5)))


def test_a_zero_rotation_quaternion_names_the_node(tmp_path):
    path = broken(tmp_path, lambda d: d["nodes"][1].update(rotation=[0, 0, 0, 0]))
    with pytest.raises(MeshFileError, match="node 1: rotation is the zero quaternion"):
        load(path)
