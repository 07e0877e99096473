"""Mandelbrot and Julia sets: membership at known points, the counts against a plain
complex-arithmetic loop written here, image order, independence of the thread count,
coloring through a color table, and the iteration limit."""

import numpy as np
import pytest

import scanline as sl
from scanline.errors import ArgumentTypeError, ArgumentValueError
from scanline.fractals import colorize, julia, mandelbrot


def count_at(c, max_iterations=500):
    """The kernel's count at one point: a 1 x 1 image centered on it."""
    return int(mandelbrot(1, 1, center=(c.real, c.imag), span=1e-12,
                          max_iterations=max_iterations)[0, 0])


@pytest.mark.parametrize("c", [0, -1, -2, 0.25, 1j, -0.1225611669 + 0.7448617666j])
def test_known_members_do_not_escape(c):
    # 0 and -1 are fixed and 2-cycle points, -2 the boundary's tip (z stays at 2),
    # 0.25 the cusp (z -> 1/2 slowly), i falls into the cycle -1 + i, -i, and the
    # last the center of the period-3 bulb (z returns to 0 every three steps)
    assert count_at(complex(c)) == 500


@pytest.mark.parametrize("c, escapes_after", [(1, 3), (0.5, 5), (-2.01, 1), (2j, 2)])
def test_outside_points_escape_after_the_iterations_by_hand(c, escapes_after):
    # c = 1: z = 0, 1, 2, 5: |z| > 2 after three iterations
    z, n = 0j, 0
    while abs(z) <= 2 and n < 500:
        z, n = z * z + complex(c), n + 1
    assert n == escapes_after
    assert count_at(complex(c)) == escapes_after


def reference(xs, ys, max_iterations, c=None):
    out = np.empty((len(ys), len(xs)), np.int64)
    for r, y in enumerate(ys):
        for k, x in enumerate(xs):
            z, cc = (complex(x, y), c) if c is not None else (0j, complex(x, y))
            n = 0
            while n < max_iterations and z.real * z.real + z.imag * z.imag <= 4.0:
                z = z * z + cc
                n += 1
            out[r, k] = n
    return out


def pixel_centers(width, height, center, span):
    step = span / width
    xs = center[0] + (np.arange(width) + 0.5 - width / 2) * step
    ys = center[1] + (height / 2 - np.arange(height) - 0.5) * step    # top row first
    return xs, ys


@pytest.mark.parametrize("center, span", [((-0.5, 0.0), 3.0), ((-0.745, 0.113), 0.02)])
def test_counts_equal_a_complex_arithmetic_loop_in_image_order(center, span):
    got = mandelbrot(40, 27, center=center, span=span, max_iterations=120)
    xs, ys = pixel_centers(40, 27, center, span)
    np.testing.assert_array_equal(got, reference(xs, ys, 120))
    c = complex(-0.8, 0.156)
    got = julia(40, 27, c=c, center=center, span=span, max_iterations=120)
    np.testing.assert_array_equal(got, reference(xs, ys, 120, c))


def test_the_set_is_symmetric_about_the_real_axis_with_the_top_row_first():
    up = mandelbrot(32, 20, center=(-0.6, 0.4), span=1.5, max_iterations=64)
    down = mandelbrot(32, 20, center=(-0.6, -0.4), span=1.5, max_iterations=64)
    np.testing.assert_array_equal(up, down[::-1])
    # the top row (imaginary part 0.4 + 0.7) lies farther from the set: it escapes sooner
    assert up[0].mean() < up[-1].mean()


def test_counts_do_not_depend_on_the_thread_count():
    numba = pytest.importorskip("numba")
    before = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        one = mandelbrot(97, 61, max_iterations=200)
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
        many = mandelbrot(97, 61, max_iterations=200)
    finally:
        numba.set_num_threads(before)
    np.testing.assert_array_equal(one, many)


def test_colorize_uses_the_tables_first_color_for_the_set():
    counts = mandelbrot(30, 20, max_iterations=60)
    table = sl.color.gray_table(16)
    fb = colorize(counts, 60, table)
    assert fb.mode == "P"
    rgb = np.asarray(fb.to_pil().convert("RGB"))
    np.testing.assert_array_equal(rgb[counts == 60], 0)
    assert (rgb[counts < 60] > 0).all()
    cycled = colorize(counts, 60, table, cycle=True)
    index = cycled.to_array()
    np.testing.assert_array_equal(index[counts < 60], 1 + counts[counts < 60] % 15)


@pytest.mark.parametrize("call, error, match", [
    (lambda: mandelbrot(10**5, 10**5, max_iterations=10**4), ArgumentValueError,
     "max_iterations: .* more than the limit of 10,000,000,000"),
    (lambda: mandelbrot(0, 10), ArgumentValueError, "width must be >= 1"),
    (lambda: mandelbrot(10, 10, span=0), ArgumentValueError, "span must be > 0"),
    (lambda: mandelbrot(10, 10, center=(float("nan"), 0)), ArgumentValueError, "center"),
    (lambda: mandelbrot(10, 10, max_iterations=0), ArgumentValueError, "max_iterations"),
    (lambda: mandelbrot(10, 10, center=(1.7e308, 0), span=1e308), ArgumentValueError,
     "beyond float64"),
    (lambda: julia(10, 10, c="i"), ArgumentTypeError, "c must be a complex"),
    (lambda: julia(10, 10, c=complex(float("inf"), 0)), ArgumentValueError, "c must be finite"),
    (lambda: colorize(np.array([[5]]), 4), ArgumentValueError, "0..max_iterations"),
    (lambda: colorize(np.zeros((2, 2), np.int64), 4, ["black"]), ArgumentValueError,
     "at least 2 colors"),
])
def test_bad_input_is_named(call, error, match):
    with pytest.raises(error, match=match):
        call()
