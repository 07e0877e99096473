"""Shape morphing (Hearn & Baker's equalization) and Beier–Neely image morphing."""

import numpy as np
import pytest

import scanline as sl
from scanline.animation import beier_neely, equalization, equalize, morph, warp

RNG = np.random.default_rng(5)


def test_triangle_to_quadrilateral_counts():
    # Hearn & Baker's example, as open polylines: L = 2 and 3 edges, V = 3 and 4
    e = equalization(3, 4, closed=False)
    assert (e.edges_max, e.edges_min, e.n_e, e.n_s) == (3, 2, 1, 1)     # 3 mod 2, int(3/2)
    assert (e.vertices_max, e.vertices_min, e.n_ls, e.n_p) == (4, 3, 1, 1)
    # and as closed polygons: 4 mod 3 = 1 edge split in two, the other two kept
    c = equalization(3, 4)
    assert (c.n_e, c.n_s) == (1, 1)


def test_triangle_to_quadrilateral_shapes():
    triangle = [(0, 0), (4, 0), (0, 3)]
    square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    a, b, added_a, added_b = equalize(triangle, square, return_added=True)
    np.testing.assert_array_equal(a, [(0, 0), (4, 0), (2, 1.5), (0, 3)])   # the hypotenuse split
    np.testing.assert_array_equal(b, square)
    assert added_a.tolist() == [False, False, True, False] and not added_b.any()
    np.testing.assert_array_equal(morph(triangle, square, 0), a)
    np.testing.assert_array_equal(morph(triangle, square, 1), b)
    np.testing.assert_allclose(morph(triangle, square, [0.25, 0.5])[1], (a + b) / 2)


def _polygon(n):
    angles = np.sort(RNG.uniform(0, 2 * np.pi, n))
    return np.stack([np.cos(angles), np.sin(angles)], 1) * RNG.uniform(1, 5, (n, 1))


@pytest.mark.parametrize("closed", [True, False])
def test_random_polygons_follow_the_rules(closed):
    for _ in range(60):
        na, nb = RNG.integers(3, 25, 2)
        a, b = _polygon(int(na)), _polygon(int(nb))
        ea, eb, ma, mb = equalize(a, b, closed=closed, return_added=True)
        assert len(ea) == len(eb) == max(na, nb)
        small, big, mask = (a, ea, ma) if na < nb else (b, eb, mb)
        if na == nb:
            assert not ma.any() and not mb.any()
            continue
        # the original vertices are kept, in order; every added vertex lies on an edge
        np.testing.assert_array_equal(big[~mask], small)
        e = equalization(len(small), len(big), closed=closed)
        edges = len(small) if closed else len(small) - 1
        pieces = np.diff(np.flatnonzero(np.concatenate([~mask, [True]])))[:edges]
        # N_e edges in N_s + 1 sections, the rest in N_s (Hearn & Baker §16-5)
        assert sorted(pieces.tolist()) == sorted([e.n_s + 1] * e.n_e + [e.n_s] * (edges - e.n_e))
        if not closed:   # the vertex rule: N_p points on N_ls sections, N_p - 1 on the rest
            assert sorted((pieces - 1).tolist()) == sorted(
                [e.n_p] * e.n_ls + [e.n_p - 1] * (len(small) - 1 - e.n_ls))


def test_align_removes_the_twist():
    square = np.array([(0, 0), (1, 0), (1, 1), (0, 1)], float)
    turned = np.roll(square[::-1], 2, axis=0)          # same square, other start and direction
    a, b = equalize(square, turned, align=True)
    np.testing.assert_array_equal(b, square)


# -- Beier–Neely ---------------------------------------------------------------------------
def reference(img_a, img_b, lines_a, lines_b, t, a=1.0, b=2.0, p=0.5):
    """Beier & Neely's field morph in plain vectorized numpy (their pseudo-code: X' =
    P' + u (Q' - P') + v perp(Q' - P') / |Q' - P'| per line, weighted), storage rows
    bottom-up, bilinear sampling with clamped edges."""
    h, w = img_a.shape[:2]
    y, x = np.mgrid[0:h, 0:w].astype(float)
    lines_t = lines_a + t * (lines_b - lines_a)

    def source_points(src_lines):
        sx = np.zeros_like(x)
        sy = np.zeros_like(y)
        total = np.zeros_like(x)
        for (px, py, qx, qy), (spx, spy, sqx, sqy) in zip(lines_t, src_lines):
            dx, dy = qx - px, qy - py
            length = np.hypot(dx, dy)
            u = ((x - px) * dx + (y - py) * dy) / length ** 2
            v = ((x - px) * -dy + (y - py) * dx) / length
            sdx, sdy = sqx - spx, sqy - spy
            slen = np.hypot(sdx, sdy)
            xs = spx + u * sdx + v * -sdy / slen
            ys = spy + u * sdy + v * sdx / slen
            dist = np.where(u < 0, np.hypot(x - px, y - py),
                            np.where(u > 1, np.hypot(x - qx, y - qy), np.abs(v)))
            weight = (length ** p / (a + dist)) ** b
            sx += (xs - x) * weight
            sy += (ys - y) * weight
            total += weight
        return x + sx / total, y + sy / total

    def sample(img, xs, ys):
        xs = np.clip(xs, 0, w - 1)
        ys = np.clip(ys, 0, h - 1)
        x0, y0 = np.floor(xs).astype(int), np.floor(ys).astype(int)
        x1, y1 = np.minimum(x0 + 1, w - 1), np.minimum(y0 + 1, h - 1)
        fx, fy = (xs - x0)[..., None], (ys - y0)[..., None]
        top = img[y0, x0] * (1 - fx) + img[y0, x1] * fx
        bottom = img[y1, x0] * (1 - fx) + img[y1, x1] * fx
        return top * (1 - fy) + bottom * fy

    va = sample(img_a.astype(float), *source_points(lines_a))
    vb = sample(img_b.astype(float), *source_points(lines_b))
    return np.clip(np.floor((1 - t) * va + t * vb + 0.5), 0, 255).astype(np.uint8)


def _images(h=40, w=56):
    a = RNG.integers(0, 256, (h, w, 3), dtype=np.uint8)
    b = RNG.integers(0, 256, (h, w, 3), dtype=np.uint8)
    return a, b


@pytest.mark.parametrize("t", [0.0, 0.3, 0.5, 1.0])
def test_beier_neely_against_numpy_reference(t):
    a, b = _images()
    la = np.array([[5, 5, 40, 10], [10, 30, 30, 35], [50, 2, 45, 38]], float)
    lb = la + RNG.uniform(-6, 6, la.shape)
    got = beier_neely(a, b, la, lb, t)
    # arrays are in image order; the reference works on storage rows (y up)
    want = reference(a[::-1], b[::-1], la, lb, t)[::-1]
    diff = np.abs(got.astype(int) - want.astype(int))
    assert diff.max() <= 1 and (diff > 0).mean() < 0.01      # float rounding at halves only


def test_identical_lines_are_a_cross_dissolve():
    a, b = _images()
    lines = RNG.uniform(0, 40, (5, 4))
    for t in (0.0, 0.25, 0.5, 0.8, 1.0):
        got = beier_neely(a, b, lines, lines, t)
        want = np.floor((1 - t) * a + t * b.astype(float) + 0.5).astype(np.uint8)
        np.testing.assert_array_equal(got, want)


def test_single_line_translation_moves_the_image():
    fb = sl.FrameBuffer(40, 30, mode="L")
    sl.draw.fill_circle(fb, 12, 15, 5, color=255)
    moved = warp(fb, [[10, 5, 10, 25]], [[20, 5, 20, 25]])       # features move 10 right
    expected = sl.FrameBuffer(40, 30, mode="L")
    sl.draw.fill_circle(expected, 22, 15, 5, color=255)
    assert isinstance(moved, sl.FrameBuffer)
    np.testing.assert_array_equal(moved.to_array()[:, 15:], expected.to_array()[:, 15:])


def test_frame_buffers_and_gray():
    a = sl.FrameBuffer(20, 10, mode="L", background=0)
    b = sl.FrameBuffer(20, 10, mode="L", background=200)
    out = beier_neely(a, b, [[0, 0, 19, 9]], [[0, 0, 19, 9]], 0.5)
    assert out.mode == "L" and set(out.to_array().ravel().tolist()) == {100}
    gray = beier_neely(np.zeros((10, 20), np.uint8), np.full((10, 20), 200, np.uint8),
                       [[0, 0, 19, 9]], [[0, 0, 19, 9]], 0.25)
    assert gray.shape == (10, 20) and set(gray.ravel().tolist()) == {50}


@pytest.mark.parametrize("call,words", [
    (lambda: equalize([(0, 0), (1, 0)], [(0, 0), (1, 0), (1, 1)]), r"V >= 3"),
    (lambda: equalize([(0, 0), (1, 0), (0, float("nan"))], [(0, 0), (1, 0), (1, 1)]), "finite"),
    (lambda: equalize([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 0), (1, 0), (1, 1)]), "one dimension"),
    (lambda: morph([(0, 0), (1, 0), (0, 1)], [(0, 0), (1, 0), (1, 1)], 2), "t must lie in"),
    (lambda: beier_neely(np.zeros((4, 4), np.uint8), np.zeros((4, 5), np.uint8),
                         [[0, 0, 1, 1]], [[0, 0, 1, 1]], 0.5), "one size"),
    (lambda: beier_neely(np.zeros((4, 4), np.uint8), np.zeros((4, 4), np.uint8),
                         [[0, 0, 0, 0]], [[0, 0, 1, 1]], 0.5), r"lines_a\[0\] has zero length"),
    (lambda: beier_neely(np.zeros((4, 4), np.uint8), np.zeros((4, 4), np.uint8),
                         [[0, 0, 1, 1]], [[0, 0, 1, 1], [1, 1, 2, 2]], 0.5), "pair with"),
    (lambda: beier_neely(np.zeros((4, 4), float), np.zeros((4, 4), float),
                         [[0, 0, 1, 1]], [[0, 0, 1, 1]], 0.5), "uint8 image"),
    (lambda: beier_neely(sl.FrameBuffer(4, 4, mode="P"), sl.FrameBuffer(4, 4, mode="P"),
                         [[0, 0, 1, 1]], [[0, 0, 1, 1]], 0.5), "mode 'P'"),
    (lambda: beier_neely(np.zeros((4, 4), np.uint8), np.zeros((4, 4), np.uint8),
                         [[0, 0, 1, 1]], [[0, 0, 1, 1]], 0.5, a=0), "a > 0"),
])
def test_bad_input(call, words):
    with pytest.raises(sl.ScanlineError, match=words):
        call()
