"""The fast path of animated scenes: the frame plan (the base display file patched per
frame) and the batched painter draw exactly the pixels of building each frame's scene
in full and interpreting it primitive by primitive."""

import copy
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import scanline as sl
from scanline.display.interpreter import drawing_order
from scanline.scene import AnimatedScene, Scene, SceneError, painter
from scanline.scene.plan import FramePlan

SCENES = os.path.join(os.path.dirname(sl.__file__), "data", "scenes")


def reference(anim, index):
    """Frame ``index`` the straightforward way: the frame's data checked and built as
    a whole scene, drawn by the display-file interpreter."""
    return Scene(anim.data_at(index)).raster().to_array()


def painted(scene):
    """A static scene drawn by the painter."""
    c = scene.canvas
    fb = sl.FrameBuffer(c.width, c.height, mode=c.mode, background=c.background)
    if c.shading is not None:
        c.shading.draw(fb)
    df = scene.display_file
    painter.paint(fb, drawing_order(df), df, c.antialias, c.highlight)
    return fb.to_array()


@pytest.mark.parametrize("name", sorted(f[:-5] for f in os.listdir(SCENES) if f.endswith(".toml")))
def test_the_painter_draws_every_bundled_scene_as_the_interpreter(name):
    scene = sl.scene.load(sl.scene.example(name))
    np.testing.assert_array_equal(painted(scene), scene.raster().to_array())


def test_bundled_animation_frames_equal_the_full_build():
    anim = sl.scene.load_animated(sl.scene.example("bouncing_ball"))
    assert isinstance(anim._frame_plan(), FramePlan)    # a path, a color and a morph
    for i in range(len(anim)):
        np.testing.assert_array_equal(anim.frame(i).to_array(), reference(anim, i))


def bench_like(count=40, seed=3):
    """Scattered segments of the animation benchmark's kind (smaller)."""
    rng = np.random.default_rng(seed)
    colors = ["crimson", "navy", "teal", "orange"]
    data = {"version": 2, "canvas": {"width": 160, "height": 120},
            "segments": [], "animation": {"fps": 4, "duration": 1.0, "tracks": []}}
    for k in range(count):
        cx, cy = rng.uniform(10, 150), rng.uniform(10, 110)
        c = colors[k % len(colors)]
        data["segments"].append({"name": f"s{k}", "transform": [
            {"rotate": {"degrees": 0.0, "pivot": [cx, cy]}}, {"translate": [0.0, 0.0]}],
            "primitives": [
                {"type": "polygon", "points": [[cx - 6, cy - 5], [cx + 6, cy - 5], [cx, cy + 7]],
                 "color": c},
                {"type": "circle", "center": [cx, cy], "radius": 2.5, "fill": True, "color": "white"},
                {"type": "ellipse", "center": [cx + 5, cy - 4], "rx": 4.0, "ry": 2.0, "color": c},
                {"type": "polyline", "points": [[cx - 7, cy - 8], [cx, cy - 10], [cx + 7, cy - 8]],
                 "color": "black", "width": 3}]})
        data["animation"]["tracks"] += [
            {"target": f"segments[s{k}].transform[0].rotate.degrees",
             "keys": [{"time": 0, "value": 0.0, "ease": "ease-in-out-sine"},
                      {"time": 1, "value": float(rng.uniform(-200, 200))}]},
            {"target": f"segments[s{k}].transform[1].translate", "interpolation": "catmull-rom",
             "keys": [{"time": 0, "value": [0.0, 0.0]},
                      {"time": 0.5, "value": rng.uniform(-9, 9, 2).tolist()},
                      {"time": 1, "value": [0.0, 0.0]}]}]
    return data


def test_scattered_primitives_are_drawn_in_few_calls():
    anim = AnimatedScene(bench_like())
    plan = anim._frame_plan()
    fb = sl.FrameBuffer(160, 120)
    device = sl.display.RasterDevice(fb)
    todo = painter.items(plan.segments_at(anim.data_at(2)), plan.display_file, fb, device,
                         "magenta")
    groups = painter.batches(todo, 160, 120)
    assert len(todo) == 160 and len(groups) < len(todo) / 3
    for i in range(len(anim)):
        np.testing.assert_array_equal(anim.frame(i).to_array(), reference(anim, i))


def test_items_move_only_past_items_they_do_not_touch():
    def calls(second):
        # a red square, a blue stroke over it, another red square
        data = {"version": 1, "canvas": {"width": 80, "height": 40}, "segments": [
            {"name": "a", "primitives": [{"type": "polygon", "color": "red",
                                          "points": [[2, 2], [12, 2], [12, 12], [2, 12]]}]},
            {"name": "b", "primitives": [{"type": "polyline", "color": "blue", "width": 3,
                                          "points": [[0, 7], [18, 7]]}]},
            {"name": "c", "primitives": [{"type": "polygon", "color": "red",
                                          "points": second}]}]}
        scene = Scene(data)
        fb = sl.FrameBuffer(80, 40)
        df = scene.display_file
        todo = painter.items(drawing_order(df), df, fb, sl.display.RasterDevice(fb), "magenta")
        np.testing.assert_array_equal(painted(scene), scene.raster().to_array())
        return [[item.kind for item in group] for group in painter.batches(todo, 80, 40)]

    # over the stroke: drawn after it
    assert calls([[14, 4], [24, 4], [24, 10], [14, 10]]) == [["area"], ["stroke"], ["area"]]
    # away from it: filled in the first call, with the first square
    assert calls([[50, 25], [60, 25], [60, 35], [50, 35]]) == [["area", "area"], ["stroke"]]


@pytest.mark.parametrize("target, value", [
    ("canvas.background", ["white", "black"]),
    ("window[2]", [39.0, 20.0]),
    ("segments[dot].priority", [0.0, 2.0]),
])
def test_tracks_outside_segments_build_each_frame(target, value):
    data = {"version": 2, "canvas": {"width": 40, "height": 20, "background": "white"},
            "window": [0, 0, 39, 19],
            "segments": [{"name": "dot", "priority": 0.0, "primitives": [
                {"type": "circle", "center": [8, 10], "radius": 4, "fill": True,
                 "color": "teal"}]}],
            "animation": {"fps": 4, "tracks": [
                {"target": target, "keys": [{"time": 0, "value": value[0]},
                                            {"time": 1, "value": value[1]}]}]}}
    anim = AnimatedScene(data)
    assert anim._frame_plan() is None
    for i in range(len(anim)):
        np.testing.assert_array_equal(anim.frame(i).to_array(), reference(anim, i))


def test_a_bad_value_in_a_frame_is_reported_as_the_full_build_reports_it():
    data = {"version": 2, "canvas": {"width": 40, "height": 20},
            "segments": [{"name": "dot", "transform": [{"scale": 1.0}], "primitives": [
                {"type": "circle", "center": [8, 10], "radius": 3, "fill": True}]}],
            "animation": {"fps": 4, "tracks": [
                {"target": "segments[dot].primitives[0].radius",
                 "keys": [{"time": 0, "value": 3}, {"time": 1, "value": -3},
                          {"time": 2, "value": 3}]},
                {"target": "segments[dot].transform[0].scale",
                 "keys": [{"time": 0, "value": 1}, {"time": 2, "value": 2}]}]}}
    anim = AnimatedScene(data)
    assert anim._frame_plan() is not None
    with pytest.raises(SceneError) as full:
        Scene(anim.data_at(4))
    with pytest.raises(SceneError) as fast:
        anim.frame(4)
    assert "radius must be >= 0" in full.value.message
    assert fast.value.message == f"frame 4 (t = 1 s): {full.value.message}"
    assert fast.value.path == full.value.path == "segments[0].primitives[0].radius"


# -- generated animated scenes ----------------------------------------------------------------
COLORS = ["black", "white", "crimson", "navy", "#ff000080", [10, 200, 30], [0, 0, 255, 128],
          "gold"]
coord = st.floats(-30, 90, allow_nan=False).map(lambda x: round(x, 2))
point = st.tuples(coord, coord).map(list)
color = st.sampled_from(COLORS)
named = st.sampled_from([c for c in COLORS if isinstance(c, str)])
line = st.fixed_dictionaries({}, optional={
    "width": st.sampled_from([1, 2, 3, 5.5]), "cap": st.sampled_from(["butt", "round", "square"]),
    "join": st.sampled_from(["miter", "round", "bevel"]), "dash": st.sampled_from([[4, 2], "dotted"])})


@st.composite
def primitive(draw):
    kind = draw(st.sampled_from(["polygon", "polygon", "circle", "ellipse", "polyline",
                                 "polyline", "markers", "text"]))
    p = {"type": kind, "color": draw(color)}
    if kind == "polygon":
        p["points"] = draw(st.lists(point, min_size=3, max_size=6))
        p["rule"] = draw(st.sampled_from(["even-odd", "nonzero"]))
        if draw(st.integers(0, 5)) == 0:
            p["style"] = draw(st.sampled_from(["hollow", "hatch:45:4"]))
        if draw(st.integers(0, 5)) == 0:
            p["edge"] = draw(color)
    elif kind in ("circle", "ellipse"):
        p["center"] = draw(point)
        p["fill"] = draw(st.booleans())
        if kind == "circle":
            p["radius"] = draw(st.floats(0, 25).map(lambda x: round(x, 2)))
        else:
            p["rx"], p["ry"] = draw(st.floats(0, 25)), draw(st.floats(0, 12))
            p["angle"] = {"degrees": draw(st.floats(-90, 90))}
        if not p["fill"]:
            p.update(draw(line))
    elif kind == "polyline":
        p["points"] = draw(st.lists(point, min_size=1, max_size=5))
        p["closed"] = draw(st.booleans())
        p.update(draw(line))
    elif kind == "markers":
        p["points"] = draw(st.lists(point, min_size=1, max_size=3))
    else:
        p.update(position=draw(point), string="Ab", height=8.0)
    return p


def step(draw, kind):
    if kind == "rotate":
        return {"rotate": {"degrees": draw(st.floats(-180, 180)), "pivot": draw(point)}}
    if kind == "translate":
        return {"translate": draw(point)}
    return {"scale": draw(st.floats(0.25, 2.0))}


@st.composite
def animated_scene(draw):
    mode = draw(st.sampled_from(["RGB", "RGB", "RGBA", "L", "P", "1"]))
    data = {"version": 2, "canvas": {
        "width": 48, "height": 36, "mode": mode, "antialias": draw(st.integers(0, 7)) == 0,
        "background": "white" if mode != "1" else 0}, "segments": [],
        "animation": {"fps": 4, "duration": 1.0, "tracks": []}}
    if draw(st.booleans()):
        data["viewports"] = [{"name": "left", "viewport": [0, 0, 0.6, 1], "window": [-10, -10, 70, 50]},
                             {"name": "right", "viewport": [0.4, 0.2, 1, 0.9], "clip": draw(st.booleans())}]
    tracks = data["animation"]["tracks"]
    for k in range(draw(st.integers(1, 4))):
        kinds = draw(st.lists(st.sampled_from(["rotate", "translate", "scale"]), max_size=3))
        seg = {"name": f"s{k}", "transform": [step(draw, kind) for kind in kinds],
               "primitives": draw(st.lists(primitive(), min_size=1, max_size=4))}
        if "viewports" in data:
            seg["viewport"] = draw(st.sampled_from(["left", "right", ["left", "right"]]))
        if draw(st.integers(0, 4)) == 0:
            seg["priority"] = draw(st.sampled_from([-1.0, 1.0]))
        if draw(st.integers(0, 6)) == 0:
            seg["highlighted"] = True
        data["segments"].append(seg)
        for j, kind in enumerate(kinds):
            if draw(st.booleans()):
                target = {"rotate": "rotate.degrees", "translate": "translate",
                          "scale": "scale"}[kind]
                value = copy.deepcopy(seg["transform"][j][kind])
                start = value["degrees"] if kind == "rotate" else value
                end = (draw(st.floats(-180, 180)) if kind == "rotate" else draw(point)
                       if kind == "translate" else draw(st.floats(0.25, 2.0)))
                tracks.append({"target": f"segments[s{k}].transform[{j}].{target}",
                               "keys": [{"time": 0, "value": start}, {"time": 1, "value": end}]})
        for j, p in enumerate(seg["primitives"]):
            if draw(st.integers(0, 2)) == 0:
                key = "radius" if p["type"] == "circle" else "points" \
                    if p["type"] in ("polygon", "polyline") else "color"
                if key == "color" and not isinstance(p["color"], str):
                    continue        # (a color track interpolates named or hex colors)
                end = draw(st.floats(0, 25)) if key == "radius" else draw(named) \
                    if key == "color" else [[x + 7, y - 5] for x, y in p["points"]]
                tracks.append({"target": f"segments[s{k}].primitives[{j}].{key}",
                               "keys": [{"time": 0, "value": p[key]}, {"time": 1, "value": end}]})
    if not tracks:
        tracks.append({"target": "segments[s0].primitives[0].color",
                       "keys": [{"time": 0, "value": "navy"}, {"time": 1, "value": "gold"}]})
    return data


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=animated_scene())
def test_generated_animations_draw_the_frames_of_the_full_build(data):
    anim = AnimatedScene(data)
    for i in range(len(anim)):
        np.testing.assert_array_equal(anim.frame(i).to_array(), reference(anim, i),
                                      err_msg=f"frame {i}")
