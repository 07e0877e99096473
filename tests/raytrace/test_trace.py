"""``scanline trace ray-tracing X Y``: the ray tree of one pixel, whose summed
intensities are the pixel sl.render draws."""

import json
import subprocess
import sys

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentValueError
from scanline.trace.raytracing import HEIGHT, WIDTH, scene


def rendered(max_depth=5):
    meshes, materials, lights, camera = scene()
    fb = sl.FrameBuffer(WIDTH, HEIGHT, background=(40, 60, 90))
    sl.render(fb, meshes, camera, method="ray-tracing", shading="phong", materials=materials,
              lights=lights, max_depth=max_depth)
    return fb


@pytest.mark.parametrize("x, y", [(20, 11), (8, 12), (16, 3)])
def test_summed_intensities_are_the_rendered_pixel(x, y):
    table = sl.trace.ray_tracing(x, y)
    kinds = [r["kind"] for r in table.rows]
    assert kinds[0] == "primary" and table.rows[0]["depth"] == 1
    rays = [r for r in table.rows if r["kind"] != "shadow"]
    # every ray's parent is a ray before it, one level up
    depth = {r["ray"]: r["depth"] for r in rays}
    for r in rays[1:]:
        assert depth[r["parent"]] == r["depth"] - 1
    total = np.sum([[r["weight"] * r[c] for c in ("I_r", "I_g", "I_b")] for r in rays], axis=0)
    last = table.rows[-1]
    assert total == pytest.approx([last["sum_r"], last["sum_g"], last["sum_b"]])
    stored = sl.shading.encode(total, 2.2)
    fb = rendered()
    assert fb.to_array()[HEIGHT - 1 - y, x].tolist() == stored.tolist()


def test_mirror_pixel_has_a_reflected_ray_and_glass_a_refracted_one():
    mirror = sl.trace.ray_tracing(8, 12)
    assert "reflected" in [r["kind"] for r in mirror.rows]
    glass = sl.trace.ray_tracing(20, 11)
    assert {"reflected", "refracted", "shadow"} <= {r["kind"] for r in glass.rows}
    assert max(r["depth"] for r in glass.rows if r["kind"] != "shadow") <= 5
    assert any("intersections of the primary ray" in n for n in glass.notes)


def test_depth_limit_one_has_no_secondary_rays():
    t = sl.trace.ray_tracing(20, 11, max_depth=1)
    assert {r["kind"] for r in t.rows} <= {"primary", "shadow"}


def test_bad_pixel_and_depth():
    with pytest.raises(ArgumentValueError, match="x"):
        sl.trace.ray_tracing(WIDTH, 0)
    with pytest.raises(ArgumentValueError, match="max_depth"):
        sl.trace.ray_tracing(1, 1, max_depth=10**6)


def test_command_line_json():
    out = subprocess.run([sys.executable, "-m", "scanline", "trace", "ray-tracing", "20", "11",
                          "--format", "json"], capture_output=True, text=True, check=True)
    rows = json.loads(out.stdout)
    assert rows == json.loads(sl.trace.ray_tracing(20, 11).to_json())


def test_distributed_rays_are_the_same_in_the_trace_and_the_render():
    """Area-light and glossy samples: the trace (the kernel run as Python) and the render
    (compiled) draw the same random numbers for the same seed and sample."""
    meshes, materials, _, camera = scene()
    materials[1] = sl.lighting.Material(color=(255, 80, 80), kd=0.2, reflectivity=0.8,
                                        roughness=0.2)
    lights = [sl.lighting.AmbientLight(0.15),
              sl.lighting.AreaLight((2, 5, 3), (2, 0, 0), (0, 0, 2), samples=3)]
    fb = sl.FrameBuffer(WIDTH, HEIGHT, background=(40, 60, 90))
    sl.render(fb, meshes, camera, method="ray-tracing", shading="phong", materials=materials,
              lights=lights, seed=7)
    for x, y in [(8, 12), (9, 10), (20, 11)]:
        t = sl.trace.ray_tracing(x, y, materials=materials, lights=lights, seed=7)
        last = t.rows[-1]
        total = [last["sum_r"], last["sum_g"], last["sum_b"]]
        assert fb.to_array()[HEIGHT - 1 - y, x].tolist() == \
            sl.shading.encode(total, 2.2).tolist()
