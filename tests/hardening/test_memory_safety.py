"""Issue 11, item 1: every integer array that indexes (counts, offsets, color-table
indices) is validated before a kernel trusts it.

The hostile calls run in a child process: before the fix they corrupted the heap,
segfaulted or hung, which would take the test session down with them.
"""

import json
import subprocess
import sys

import numpy as np
import pytest

import scanline as sl
from scanline import _validate as v

pytestmark = pytest.mark.boundscheck   # run again with NUMBA_BOUNDSCHECK=1 (.ci/run)

V = np.array([(1.0, 1.0), (10.0, 2.0), (5.0, 9.0)])

#: name -> code run in a child with ``sl``, ``np``, ``V`` (a triangle) and ``fb``.
HOSTILE = {
    "fills_flat uint64 offsets": "sl.draw.antialias.fills_flat(sl.FrameBuffer(16, 12, mode='L'), "
                                 "V, np.array([0, 2**64 - 5, 3], np.uint64), [0, 2])",
    "fills_flat huge offsets": "sl.draw.antialias.fills_flat(fb, V, np.array([0, 2**62, 3]), [0, 2])",
    "fills_flat shape offsets wrap": "sl.draw.antialias.fills_flat(fb, V, [0, 3], "
                                     "np.array([0, 2**64 - 1], np.uint64))",
    "polylines counts overflow": "sl.draw.polylines(fb, V, counts=np.array([2**63, 2**63, 3], "
                                 "np.uint64))",
    "polylines thick counts overflow": "sl.draw.polylines(fb, V, width=3, counts=np.array("
                                       "[2**63, 2**63, 3], np.uint64))",
    "clip polygons counts overflow": "sl.clip.polygons(V, (1, 1, 9, 6), counts=np.array("
                                     "[2**63, 2**63, 3], np.uint64))",
    "polygons counts overflow": "sl.draw.polygons(fb, V, counts=np.array([2**63, 2**63, 3], "
                                "np.uint64))",
    "fills counts overflow": "sl.draw.antialias.fills(fb, V, counts=np.array([2**63, 2**63, 3], "
                             "np.uint64))",
    "polygons counts int64 wrap": "sl.draw.polygons(fb, V, counts=np.array([2**62] * 4 + [3]))",
    "polygons counts negative": "sl.draw.polygons(fb, V, counts=[5, -2])",
    "polygons counts python ints": "sl.draw.polygons(fb, V, counts=[2**70, -2**70 + 3])",
    "from_array P short table": "sl.FrameBuffer.from_array(np.full((48, 64), 255, np.uint8), "
                                "mode='P', color_table=['red'])",
}

CHILD = r"""
import json, sys
import numpy as np
import scanline as sl
V = np.array([(1.0, 1.0), (10.0, 2.0), (5.0, 9.0)])
out = {}
for name, code in json.loads(sys.argv[1]).items():
    fb = sl.FrameBuffer(64, 48)
    try:
        exec(code)
        out[name] = ["accepted", ""]
    except Exception as e:
        out[name] = [type(e).__name__ if not isinstance(e, sl.ScanlineError) else "ScanlineError",
                     str(e)]
print(json.dumps(out))
"""


@pytest.fixture(scope="module")
def outcomes():
    proc = subprocess.run([sys.executable, "-c", CHILD, json.dumps(HOSTILE)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, f"the child died (status {proc.returncode}): {proc.stderr[-2000:]}"
    return json.loads(proc.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_index_arrays_are_refused(outcomes, name):
    kind, message = outcomes[name]
    assert kind == "ScanlineError", (kind, message)
    names = ("counts", "contour_offsets", "shape_offsets", "color_table", "array")
    assert any(n in message for n in names), message


def test_from_array_mode_p_names_the_index_and_the_table():
    with pytest.raises(sl.ArgumentValueError, match="index 255 but color_table has 1 entries"):
        sl.FrameBuffer.from_array(np.full((4, 6), 255, np.uint8), mode="P", color_table=["red"])
    fb = sl.FrameBuffer.from_array(np.full((4, 6), 1, np.uint8), mode="P",
                                   color_table=["red", "blue"])
    assert fb.get_pixel(0, 0) == 1


def test_from_pil_pads_a_short_palette_with_black():
    from PIL import Image
    img = Image.new("P", (3, 2))
    img.putpalette([255, 0, 0, 0, 255, 0])          # two entries
    img.putpixel((1, 0), 5)                           # an index past them
    fb = sl.FrameBuffer.from_pil(img)
    assert fb.color_table.tolist()[:2] == [[255, 0, 0], [0, 255, 0]]
    assert fb.color_table.tolist()[5] == [0, 0, 0]
    assert fb.get_pixel(1, 1) == 5


# -- the validation path itself -------------------------------------------------------------
def test_index_array_requires_an_integer_dtype():
    for bad in ([1.0, 2.0], np.array([True, False]), ["1", "2"], [1, None], 3.5):
        with pytest.raises(sl.ArgumentTypeError, match="offsets"):
            v.index_array("offsets", bad)


def test_index_array_checks_the_range_in_the_arrays_own_dtype():
    big = np.array([1, 2**64 - 1], np.uint64)
    with pytest.raises(sl.ArgumentValueError, match=r"offsets\[1\] is 18446744073709551615"):
        v.index_array("offsets", big)
    with pytest.raises(sl.ArgumentValueError, match=r">= 0; faces\[1, 2\] is -1"):
        v.index_array("faces", [[0, 1, 2], [2, 3, -1]], shape=(None, 3))
    with pytest.raises(sl.ArgumentValueError, match=r"<= 3; faces\[0, 1\] is 4"):
        v.index_array("faces", [[0, 4, 2]], shape=(None, 3), high=3)
    with pytest.raises(sl.ArgumentValueError, match="beyond the 64-bit integer range"):
        v.index_array("counts", [2**64])


def test_index_array_converts_to_contiguous_writable_int64():
    a = np.arange(10, dtype=np.uint8)[::2]
    a.flags.writeable = False
    out = v.index_array("indices", a)
    assert out.dtype == np.int64 and out.flags.c_contiguous and out.flags.writeable
    assert out.tolist() == [0, 2, 4, 6, 8]
    assert v.index_array("faces", [], shape=(None, 3)).shape == (0, 3)


def test_index_array_checks_monotonicity_after_conversion():
    # as uint64 the difference 0 - 5 wraps to a huge positive number: the check is
    # made on the converted values
    with pytest.raises(sl.ArgumentValueError, match="must not decrease"):
        v.index_array("offsets", np.array([0, 5, 0], np.uint64), rising=True)
    with pytest.raises(sl.ArgumentValueError, match="must rise from 0 to 9"):
        v.index_array("offsets", [0, 4, 3, 9], rising=True, first=0, last=9, high=9)
    assert v.index_array("offsets", [0, 4, 4, 9], rising=True, first=0, last=9).tolist() == [0, 4, 4, 9]


def test_counts_sum_is_exact():
    # each count is within the total, but int64 arithmetic would wrap the sum to 3
    counts = np.array([2**62, 2**62, 2**62, 2**62 - 1, 4], np.int64)
    with pytest.raises(sl.ArgumentValueError, match="counts"):
        v.counts("counts", counts, 3, "points")
    assert v.exact_sum(np.array([2**62] * 4)) == 2**64
    c, offsets = v.counts("counts", np.array([1, 0, 2], np.uint16), 3, "points")
    assert c.tolist() == [1, 0, 2] and offsets.tolist() == [0, 1, 1, 3]
