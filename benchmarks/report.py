"""Format a benchmark record (the JSON that run.py writes) as text or Markdown.

    python benchmarks/report.py                          # Markdown of results/latest.json
    python benchmarks/report.py results/latest.json --text
    python benchmarks/report.py --topics                 # the topic benchmarks' targets
    python benchmarks/report.py --compile                # results/compile.json by group
"""

import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def _s(seconds):
    if seconds is None:
        return "-"
    return f"{seconds:.3f} s" if seconds >= 0.1 else f"{seconds * 1e3:.1f} ms"


def _us(us):
    return f"{us:.3g}" if us < 100 else f"{us:.0f}"


def _ratio(x):
    return f"{x:.2f}"


def _first_calls(record):
    """First call of each scanline API call in this run (the first workload using it)."""
    seen = {}
    for entry in record["workloads"].values():
        for r in entry["results"]:
            if r["library"] == "scanline":
                name = r["call"].split(" ")[0]
                seen.setdefault(name, (r["first_call_s"], r.get("first_call_cache")))
    return seen


def _compile_rows(record):
    """(call, first call this run, cache status, first call in a later process)."""
    first = _first_calls(record)
    probe = record.get("compile", {}).get("cache_load", {})
    load = probe.get("first_call_s", {})
    status = probe.get("cache", {})
    return [(call, *first[call], load.get(call), status.get(call)) for call in first]


def _sanity_lines(entry):
    s = entry["sanity"]
    parts = []
    for key, c in s["compare"].items():
        if c["identical"]:
            parts.append(f"{c['library']} {c['call']}: identical")
        else:
            parts.append(f"{c['library']} {c['call']}: {c['set_pixels']:,} "
                         f"({c['count_diff_pct']:+.1f}%, Jaccard {c['jaccard']:.3f})")
    head = (f"sanity, first {s['n_primitives']:,} primitives, set pixels vs "
            f"sl.draw.{entry['results'][0]['call'].split('.')[-1].split(' ')[0]} "
            f"= {s['set_pixels']['sl-batch']:,}:")
    return head, parts


def _scaled_note(r):
    return f"timed on {r['n_timed']:,}, scaled x{r['scale']:g}" if r["scale"] != 1 else ""


def text(record):
    out = []
    for name, e in record["workloads"].items():
        w, h = e["canvas"]
        out.append(f"== {name}: {e['description']} (RGB), seed {e['seed']} ==")
        out.append(f"  {'library':<12} {'call':<46} {'first call':>10} {'warm':>9} "
                   f"{'us/prim':>8} {'/sl batch':>9} {'/sl loop':>9}")
        for r in e["results"]:
            mark = " (info)" if r["info_only"] else ""
            note = _scaled_note(r)
            out.append(f"  {r['library']:<12} {(r['call'] + mark)[:46]:<46} "
                       f"{_s(r['first_call_s']):>10} {_s(r['warm_s']):>9} "
                       f"{_us(r['per_primitive_us']):>8} {_ratio(r['ratio_vs_sl_batch']):>9} "
                       f"{_ratio(r['ratio_vs_sl_loop']):>9}" + (f"  * {note}" if note else ""))
        head, parts = _sanity_lines(e)
        out.append("  " + head)
        out.extend("    " + p for p in parts)
        out.append("")
    if record["targets"]:
        out.append("== targets ==")
        for t in record["targets"]:
            out.append(f"  [{'MET' if t['met'] else 'NOT MET'}] {t['what']}: "
                       f"{t['value']:.2f}x (need {t['threshold']:.2f}x); {t['detail']}")
        out.append("")
    rows = _compile_rows(record)
    if rows:
        comp = record["compile"]
        out.append("== numba: first call of each scanline call (one primitive) ==")
        out.append(f"  numba cache: {comp.get('numba_cache', '?')}; import scanline.draw "
                   f"(numba included) {_s(comp.get('import_scanline_draw_s'))}, not counted")
        out.append(f"  {'call':<18} {'first call in this run':>38} {'later fresh process':>30}")
        for call, first, cache, load, lstat in rows:
            fs = f"{_s(first)} ({cache})" if cache else _s(first)
            ls = f"{_s(load)} ({lstat})" if lstat else _s(load)
            out.append(f"  {call:<18} {fs:>38} {ls:>30}")
    return "\n".join(out).rstrip()


_MD_COLUMNS = (("sl-batch", "scanline, 1 batch call"), ("sl-loop", "scanline loop"),
               ("cv2-loop", "OpenCV loop"), ("pil-loop", "Pillow loop"),
               ("sk-loop", "scikit-image loop"), ("cv2-polylines", "cv2.polylines, 1 call ‡"),
               ("cv2-fillpoly-1call", "cv2.fillPoly, 1 call ‡"))


def markdown(record):
    """A compact Markdown summary (for the top-level README): one row per workload."""
    m = record["machine"]
    out = [
        f"Measured {record['date'][:10]} on {m['cpu_model']} ({m['cpu_count_usable']} cores), "
        f"{m['python']}, numpy {m['numpy']}, numba {m['numba']}, OpenCV {m['opencv']}, "
        f"Pillow {m['pillow']}, scikit-image {m['skimage']}"
        + (" — quick run (~10x smaller workloads)" if record["quick"] else "") + ". "
        f"Best of {record['repeats']} warm runs; in parentheses, that time / scanline's "
        "batch time (> 1: scanline's batch call is faster).",
        "",
        "| workload | " + " | ".join(label for _, label in _MD_COLUMNS) + " |",
        "|---|" + "---:|" * len(_MD_COLUMNS),
    ]
    notes = []
    for name, e in record["workloads"].items():
        rows = {r["key"]: r for r in e["results"]}
        cells = []
        for key, _ in _MD_COLUMNS:
            r = rows.get(key)
            if r is None:
                cells.append("")
                continue
            cell = _s(r["warm_s"])
            if key != "sl-batch":
                cell += f" ({r['ratio_vs_sl_batch']:.2f}x)"
            if r["scale"] != 1:
                cell += " †"
                notes.append(f"{name}: {r['library']} {_scaled_note(r)}")
            cells.append(cell)
        out.append(f"| {name}: {e['description']} | " + " | ".join(cells) + " |")
    out.append("")
    if notes:
        out.append("† timed on a prefix and scaled linearly (" + "; ".join(notes) + ").")
    out.append("‡ OpenCV's one call for N two-point polylines, or for N polygons (filled by "
               "parity across all of them: a different image), for information; the targets "
               "compare with per-primitive loops, the only way the peers draw circles, "
               "ellipses and separate polygons.")
    if record["targets"]:
        out += ["", "| target | measured | met |", "|---|---:|:---:|"]
        for t in record["targets"]:
            out.append(f"| {t['what']} | {t['value']:.2f}x | {'yes' if t['met'] else '**no**'} |")
    rows = _compile_rows(record)
    if rows:
        out += ["", "| numba, first call on one primitive | compile (first call in the run) "
                "| later process (cache load) |", "|---|---:|---:|"]
        for call, first, cache, load, lstat in rows:
            fs = f"{_s(first)}" + (f" ({cache})" if cache and cache != "compiled" else "")
            ls = f"{_s(load)}" + (f" ({lstat})" if lstat and lstat != "cache hit" else "")
            out.append(f"| `{call}` | {fs} | {ls} |")
    out += ["", "Same pixels? Set pixels of the first primitives, compared with scanline's batch "
            "call (count difference, Jaccard index):"]
    for name, e in record["workloads"].items():
        s = e["sanity"]
        parts = []
        for key, c in s["compare"].items():
            label = "scanline loop" if key == "sl-loop" else dict(_MD_COLUMNS)[key].split(",")[0]
            parts.append(f"{label} identical" if c["identical"] else
                         f"{label} {c['count_diff_pct']:+.1f}% / {c['jaccard']:.3f}")
        out.append(f"- {name} ({s['n_primitives']:,}, {s['set_pixels']['sl-batch']:,} pixels): "
                   + ", ".join(parts) + ".")
    return "\n".join(out)


#: The topic benchmarks (``benchmarks/<topic>.py``), in README order.
TOPICS = ("strokes", "antialias", "text", "dither", "clip", "display", "curves", "flatten",
          "animation", "render")


def topics_markdown(folder=os.path.join(HERE, "results")):
    """One markdown table of every target recorded by the topic benchmarks
    (``results/<topic>.json``, written by ``common.Report``)."""
    out = ["| benchmark | workload | peer | peer time / scanline time | target | met |",
           "|---|---|---|---:|---|:---:|"]
    for topic in TOPICS:
        path = os.path.join(folder, f"{topic}.json")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            record = json.load(f)
        for t in record["targets"]:
            out.append(f"| {topic} ({record['date'][:10]}) | {t['workload']} | {t['peer']} | "
                       f"{t['ratio']:.2f}x | {t['text']} (>= {t['minimum']:g}) | "
                       f"{'yes' if t['met'] else 'no'} |")
    return "\n".join(out)


def compile_markdown(path=os.path.join(HERE, "results", "compile.json")):
    """The first-use budget (``results/compile.json``, written by compile.py) as one
    row per warm-up group: how many cases, the median and the worst seconds to the
    first result, and the specializations compiled on the way."""
    from scanline import warmup

    with open(path) as f:
        record = json.load(f)
    groups = {}
    for row in record["rows"]:
        call = warmup.CALLS.get(row["case"])
        group = call[0] if call else ("demo" if row["case"].startswith("scanline demo")
                                      else "command line")
        groups.setdefault(group, []).append(row)
    out = [f"Measured {record['date']} on {record['machine']}, Python {record['python']}, "
           f"numba {record['numba']}; each case in a fresh process with an empty numba cache "
           f"(SCANLINE_COMPILE={record['compile']}).", "",
           "| group | cases | median | worst case | specializations compiled |",
           "|---|---:|---:|---|---:|"]
    seconds = lambda r: r.get("seconds") or r["wall_s"]  # noqa: E731
    for group, rows in groups.items():
        times = sorted(seconds(r) for r in rows)
        worst = max(rows, key=seconds)
        label = worst["case"] + (f" [{worst['mode']}]" if worst.get("mode") else "")
        out.append(f"| {group} | {len(rows)} | {times[len(times) // 2]:.2f} s | {label}: "
                   f"{seconds(worst):.2f} s | {sum(r['specializations'] for r in rows)} |")
    worst = max((r for r in record["rows"] if not r["case"].startswith("scanline demo")),
                key=seconds)
    out += ["", f"Worst row: {worst['case']}" + (f" [{worst['mode']}]" if worst.get("mode") else "")
            + f", {seconds(worst):.2f} s; every case ran without an error: "
            + ("yes" if all(r["ok"] for r in record["rows"]) else "no")]
    return "\n".join(out)


def main(argv):
    if "--compile" in argv:
        print(compile_markdown())
        return
    if "--topics" in argv:
        print(topics_markdown())
        return
    args = [a for a in argv if not a.startswith("--")]
    path = args[0] if args else os.path.join(HERE, "results", "latest.json")
    with open(path) as f:
        record = json.load(f)
    print(text(record) if "--text" in argv else markdown(record))


if __name__ == "__main__":
    main(sys.argv[1:])
