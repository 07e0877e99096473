"""Key frames of orientation (sl.animation.RotationKeyFrames) against scipy's Slerp on
random keys at uneven times; squad through the keys; a Timeline plays them; scene
files animate a rotate.quaternion step by slerp, frames equal to static scenes."""

import math

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.scene import SceneError, loads_animated
from scanline.transform3d import Quaternion

transform = pytest.importorskip("scipy.spatial.transform")
Rotation, Slerp = transform.Rotation, transform.Slerp


def quaternions(rotations):
    return [Quaternion(w, x, y, z) for x, y, z, w in rotations.as_quat()]


@pytest.mark.parametrize("seed", range(10))
def test_slerp_tracks_agree_with_scipy_slerp_at_uneven_key_times(seed):
    rng = np.random.default_rng(seed)
    times = np.cumsum(rng.uniform(0.2, 2.0, 5))
    keys = Rotation.random(5, random_state=seed)
    # keys given three ways: quaternions, 3x3 matrices, (w, x, y, z) with either sign
    given = [quaternions(keys)[0], keys[1].as_matrix(), -quaternions(keys[2:3])[0].wxyz,
             quaternions(keys)[3], keys[4].as_matrix()]
    track = sl.animation.RotationKeyFrames(times, given)
    samples = np.linspace(times[0], times[-1], 37)
    expected = Slerp(times, keys)(samples).as_matrix()
    np.testing.assert_allclose(track.matrices(samples)[:, :3, :3], expected, atol=1e-10)
    for t, m in zip(samples[::6], expected[::6]):
        np.testing.assert_allclose(track(t).matrix3(), m, atol=1e-10)
    np.testing.assert_allclose(track(times[0] - 5).matrix3(), keys[0].as_matrix(), atol=1e-12)
    np.testing.assert_allclose(track(times[-1] + 5).matrix3(), keys[4].as_matrix(), atol=1e-12)


def test_squad_tracks_pass_through_the_keys_and_ease_shapes_time():
    keys = Rotation.random(4, random_state=3)
    track = sl.animation.RotationKeyFrames([0, 1, 2, 3], quaternions(keys),
                                           interpolation="squad")
    for t in range(4):
        np.testing.assert_allclose(track(float(t)).matrix3(), keys[t].as_matrix(), atol=1e-12)
    eased = sl.animation.RotationKeyFrames([0, 1], quaternions(keys[:2]), ease="ease-in-quad")
    plain = sl.animation.RotationKeyFrames([0, 1], quaternions(keys[:2]))
    np.testing.assert_allclose(eased(0.5).matrix3(), plain(0.25).matrix3(), atol=1e-12)


def test_a_timeline_plays_rotation_tracks():
    spin = sl.animation.RotationKeyFrames([0, 1], [Quaternion(),
                                                   Quaternion.from_axis_angle("z", math.pi)])
    timeline = sl.animation.Timeline({"spin": spin}, fps=4)
    assert len(timeline) == 5
    q = timeline.values(2)["spin"]
    assert isinstance(q, Quaternion)
    assert math.degrees(q.angle) == pytest.approx(90)
    assert timeline.key_times().tolist() == [0.0, 1.0]


@pytest.mark.parametrize("call, error, match", [
    (lambda: sl.animation.RotationKeyFrames([0, 1], [Quaternion()]), ArgumentValueError,
     "one orientation per key frame"),
    (lambda: sl.animation.RotationKeyFrames([0, 1], [Quaternion(), np.diag([1, 1, -1.0])]),
     ArgumentValueError, "rotations\\[1\\]: m is not a rotation matrix"),
    (lambda: sl.animation.RotationKeyFrames([0, 1], [Quaternion(), (0, 0, 0, 0)]),
     ArgumentValueError, "rotations\\[1\\] is the zero quaternion"),
    (lambda: sl.animation.RotationKeyFrames([0, 1], [Quaternion(), "x"]), ArgumentTypeError,
     "rotations\\[1\\] must be a Quaternion"),
    (lambda: sl.animation.RotationKeyFrames([1, 0], [Quaternion(), Quaternion()]),
     ArgumentValueError, "times must increase"),
    (lambda: sl.animation.RotationKeyFrames([0, 1], [Quaternion()] * 2, interpolation="linear"),
     ArgumentValueError, "interpolation must be one of 'slerp', 'squad'"),
])
def test_bad_rotation_tracks_are_named(call, error, match):
    with pytest.raises(error, match=match):
        call()


SCENE = """
version = 2
canvas = {width = 48, height = 36, background = "white"}
shading = {model = "flat"}

[[cameras]]
name = "eye"
eye = [4, 3, 5]
target = [0, 0, 0]
up = [0, 1, 0]

[[lights]]
type = "directional"
direction = [-1, -2, -3]

[materials.paint]
color = "#3060c0"

[[segments]]
name = "box"
[[segments.primitives]]
type = "mesh"
generator = "box"
lo = [-1, -0.5, -0.25]
hi = [1, 0.5, 0.25]
material = "paint"
transform = [{rotate = {quaternion = [1, 0, 0, 0]}}]

[animation]
fps = 4

[[animation.rotations]]
target = "segments[box].primitives[0].transform[0].rotate.quaternion"
KEYS
"""
TARGET = "segments[box].primitives[0].transform[0].rotate.quaternion"


def test_scene_rotation_tracks_slerp_and_draw_as_static_scenes():
    keys = ('keys = [{time = 0, axis = [0, 0, 1], degrees = 0}, '
            '{time = 1, euler = {seq = "xyz", degrees = [90, 0, 45]}}, '
            '{time = 2, quaternion = [0, 1, 0, 0]}]')
    anim = loads_animated(SCENE.replace("KEYS", keys))
    assert len(anim) == 9
    key_rotations = Rotation.concatenate([Rotation.identity(),
                                          Rotation.from_euler("xyz", [90, 0, 45], degrees=True),
                                          Rotation.from_quat([1, 0, 0, 0])])
    reference = Slerp([0, 1, 2], key_rotations)
    for frame in range(9):
        w, x, y, z = anim.data_at(frame)["segments"][0]["primitives"][0]["transform"][0][
            "rotate"]["quaternion"]
        got = Quaternion(w, x, y, z).matrix3()
        np.testing.assert_allclose(got, reference([frame / 4]).as_matrix()[0], atol=1e-10)
    data = anim.data_at(3)
    q = data["segments"][0]["primitives"][0]["transform"][0]["rotate"]["quaternion"]
    static = sl.scene.loads(SCENE.split("[animation]")[0].replace(
        "quaternion = [1, 0, 0, 0]", "quaternion = [" + ", ".join(map(repr, q)) + "]"))
    np.testing.assert_array_equal(anim.frame(3).to_array(), static.raster().to_array())
    assert not np.array_equal(anim.frame(3).to_array(), anim.frame(0).to_array())


@pytest.mark.parametrize("keys, match", [
    ("keys = [{time = 0, quaternion = [0, 0, 0, 0]}]", "keys\\[0\\].quaternion"),
    ("keys = [{time = 0, quaternion = [1, 0, 0, 0], axis = [0, 0, 1]}]", "one way"),
    ("keys = [{time = 0, axis = [0, 0, 1]}]", "must say its unit"),
    ("keys = [{time = 0, quaternion = [1, 0, 0, 0], degrees = 5}]", "goes with axis"),
    ("keys = [{time = 0, euler = {seq = \"xxz\", degrees = [1, 2, 3]}}]", "same axis twice"),
    ("keys = [{time = 0, euler = {seq = \"xyz\", degrees = [1, 2]}}]", "one angle per axis"),
    ("keys = [{time = 0, axis = [0, 0, 0], degrees = 5}]", "zero vector"),
    ("keys = [{time = 0, quaternion = [1, 0, 0, 0]}]\ninterpolation = \"linear\"",
     "interpolation must be one of"),
])
def test_bad_scene_rotation_keys_name_the_key(keys, match):
    with pytest.raises(SceneError, match=match) as info:
        loads_animated(SCENE.replace("KEYS", keys))
    assert "animation.rotations[0]" in str(info.value)


def test_a_rotation_track_must_target_a_quaternion():
    text = SCENE.replace(TARGET, "segments[box].primitives[0].hi").replace(
        "KEYS", "keys = [{time = 0, quaternion = [1, 0, 0, 0]}]")
    with pytest.raises(SceneError, match="rotate.quaternion"):
        loads_animated(text)
