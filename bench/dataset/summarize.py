#!/usr/bin/env python3
"""Summarises a dataset run (bench/dataset/run.sh): a Markdown table per category and overall
(cases, exact success, double-valid, time per input tet, growth, bits, peak memory), the ten
slowest cases, the failures, and a cumulative-time SVG like the paper's Fig. 14 (share of cases
finished within t seconds, log scale).

With several RESULTS_DIRs (runs of the same dataset with different `cmx map --arith`, e.g.
CMX_MAP_OPTIONS="--arith double" bench/dataset/run.sh ...), a first table has one row per run:
success rate, how many runs lost validity, in which operation, how far into the run (expansions
done at the loss / expansions of the first run's success on that case: give the exact run first)
and how many bits the exact position had there. The other
tables describe the first RESULTS_DIR.

Usage: bench/dataset/summarize.py DATASET_DIR RESULTS_DIR [RESULTS_DIR...] [--svg OUT.svg]
Standard library only.
"""
import json
import math
import os
import statistics
import sys


def category(name):
    if name.startswith("slab") and "_1_s" in name:
        return "thin, no interior vertex"
    if name.startswith("slab"):
        return "thin, 2 layers"
    return "thick"


def load(dataset, results):
    cases = []
    with open(os.path.join(dataset, "cases.txt")) as f:
        for line in f:
            name, _mesh, _bnd, tets = line.split()
            path = os.path.join(results, "reports", name + ".json")
            rep = None
            if os.path.exists(path):
                with open(path) as g:
                    rep = json.load(g)
            cases.append({"name": name, "tets": int(tets), "report": rep, "category": category(name)})
    return cases


def fmt(v, spec):
    return "-" if v is None else format(v, spec)


def median(xs):
    return statistics.median(xs) if xs else None


def row(label, cases):
    n = len(cases)
    done = [c for c in cases if c["report"] and c["report"]["status"] == "success"]
    dbl = [c for c in done if c["report"]["verdict"].get("double_valid")]
    per_tet = [c["report"]["seconds"]["total"] / c["tets"] for c in done]
    growth = [c["report"]["output"]["growth_ratio"] for c in done]
    bits = [c["report"]["bits"]["max"] for c in done]
    rss = [c["report"].get("peak_rss_kb", 0) / 1024 for c in done]
    return "| %s | %d | %d (%.1f %%) | %d (%.1f %%) | %s | %s | %s / %s | %s / %s | %s / %s |" % (
        label, n, len(done), 100 * len(done) / n if n else 0, len(dbl), 100 * len(dbl) / n if n else 0,
        fmt(median(per_tet), ".2e"), fmt(max(per_tet) if per_tet else None, ".2e"),
        fmt(statistics.mean(growth) if growth else None, ".4f"), fmt(max(growth) if growth else None, ".4f"),
        fmt(median(bits), ".0f"), fmt(max(bits) if bits else None, "d"),
        fmt(median(rss), ".0f"), fmt(max(rss) if rss else None, ".0f"))


def expansions(rep):
    e = rep["expansion"]
    return e["simple"] + e["star_shapified"] + e["inflated"] + e["automatic"]


def arith_row(cases, reference):
    """reference: name -> report of the first run (exact), to place each loss within its run."""
    reps = [c["report"] for c in cases if c["report"]]
    label = next((r["options"].get("arith", "rational") for r in reps), "?")
    n = len(cases)
    done = sum(1 for r in reps if r["status"] == "success")
    dbl = sum(1 for r in reps if r["status"] == "success" and r["verdict"].get("double_valid"))
    lost = [r for r in reps if r["status"] == "precision_lost"]
    other = n - done - len(lost)
    phases = {}
    for r in lost:
        ph = r["precision_loss"]["phase"]
        phases[ph] = phases.get(ph, 0) + 1
    where = ", ".join("%s %d" % kv for kv in sorted(phases.items(), key=lambda kv: -kv[1])) or "-"
    progress = []
    for c in cases:
        r, ref = c["report"], reference.get(c["name"])
        if r and r["status"] == "precision_lost" and ref and ref["status"] == "success" and expansions(ref):
            progress.append(r["precision_loss"]["step"] / expansions(ref))
    thick = [c for c in cases if c["category"] == "thick"]
    thick_done = sum(1 for c in thick if c["report"] and c["report"]["status"] == "success")
    bits = [r["precision_loss"]["exact_bits"] for r in lost if r["precision_loss"]["exact_bits"]]
    return "| %s | %d | %d (%.1f %%) | %d / %d | %d (%.1f %%) | %d | %d | %s | %s | %s |" % (
        label, n, done, 100 * done / n if n else 0, thick_done, len(thick), dbl, 100 * dbl / n if n else 0,
        len(lost), other, where,
        fmt(median(progress), ".2f"), fmt(median(bits), ".0f"))


def cumulative_svg(cases, path, limit):
    times = sorted(c["report"]["seconds"]["total"] for c in cases
                   if c["report"] and c["report"]["status"] == "success")
    n = len(cases)
    w, h, ml, mr, mt, mb = 700, 420, 70, 20, 40, 50
    lo, hi = 1e-2, max(limit, max(times) if times else 1)
    def sx(t):
        return ml + (math.log10(max(t, lo)) - math.log10(lo)) / (math.log10(hi) - math.log10(lo)) * (w - ml - mr)
    def sy(share):
        return mt + (1 - share) * (h - mt - mb)
    pts = ["%.1f,%.1f" % (sx(lo), sy(0))]
    for i, t in enumerate(times):
        pts.append("%.1f,%.1f" % (sx(t), sy(i / n)))
        pts.append("%.1f,%.1f" % (sx(t), sy((i + 1) / n)))
    pts.append("%.1f,%.1f" % (sx(hi), sy(len(times) / n)))
    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           '<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">' % (w, h),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="22" text-anchor="middle" font-size="14">cases mapped exactly within t seconds (%d cases)</text>' % (w // 2, n),
           '<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#444"/>' % (ml, mt, w - ml - mr, h - mt - mb)]
    for share in (0, 0.25, 0.5, 0.75, 1):
        y = sy(share)
        out.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="#ddd"/>' % (ml, w - mr, y, y))
        out.append('<text x="%d" y="%.1f" text-anchor="end">%d %%</text>' % (ml - 6, y + 4, round(share * 100)))
    e = math.floor(math.log10(lo))
    while 10 ** e <= hi * 1.0001:
        x = sx(10 ** e)
        out.append('<line x1="%.1f" x2="%.1f" y1="%d" y2="%d" stroke="#eee"/>' % (x, x, mt, h - mb))
        out.append('<text x="%.1f" y="%d" text-anchor="middle">%g</text>' % (x, h - mb + 16, 10 ** e))
        e += 1
    out.append('<text x="%d" y="%d" text-anchor="middle">seconds per case (log scale)</text>' % ((w + ml) // 2, h - 12))
    out.append('<polyline fill="none" stroke="#c0392b" stroke-width="2" points="%s"/>' % " ".join(pts))
    out.append('</svg>')
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(tmp, path)


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    svg = argv[argv.index("--svg") + 1] if "--svg" in argv else None
    dirs = [a for i, a in enumerate(argv[1:], 1) if a != "--svg" and argv[i - 1] != "--svg"]
    dataset, runs = dirs[0], dirs[1:]
    if len(runs) > 1:
        print("| arith | n | verified success | thick | double valid | precision lost | time limit or stuck "
              "| lost in (operation: cases) | median progress at loss | median exact bits at loss |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        reference = {c["name"]: c["report"] for c in load(dataset, runs[0]) if c["report"]}
        for results in runs:
            print(arith_row(load(dataset, results), reference))
        print()
    cases = load(dataset, runs[0])
    print("| cases | n | exact success | double valid | median s / input tet | max s / input tet "
          "| growth mean / max | max bits median / max | peak MiB median / max |")
    print("|---|---|---|---|---|---|---|---|---|")
    for cat in ("thick", "thin, 2 layers", "thin, no interior vertex"):
        sub = [c for c in cases if c["category"] == cat]
        if sub:
            print(row(cat, sub))
    print(row("all", cases))
    done = [c for c in cases if c["report"] and c["report"]["status"] == "success"]
    print("\nTen slowest successes:\n")
    print("| case | tets | seconds | expand | double | verify | star-shapified | pushes | growth |")
    print("|---|---|---|---|---|---|---|---|---|")
    for c in sorted(done, key=lambda c: -c["report"]["seconds"]["total"])[:10]:
        r = c["report"]
        s = r["seconds"]
        print("| %s | %d | %.2f | %.2f | %.2f | %.2f | %d | %d | %.4f |" % (
            c["name"], c["tets"], s["total"], s["expand"], s.get("double", 0), s["verify"],
            r["expansion"]["star_shapified"], r["expansion"]["pushes"], r["output"]["growth_ratio"]))
    failed = [c for c in cases if not (c["report"] and c["report"]["status"] == "success")]
    print("\nNot mapped: %d" % len(failed))
    for c in failed:
        r = c["report"]
        print("- %s: %s" % (c["name"], (r["status"] + ": " + r["message"]) if r else "no report (killed by the timeout)"))
    notdbl = [c for c in done if not c["report"]["verdict"].get("double_valid")]
    print("\nExact but not double-valid: %d" % len(notdbl))
    for c in notdbl:
        v = c["report"]["verdict"]
        print("- %s: %d inverted, %d degenerate" % (c["name"], v.get("double_inverted", 0), v.get("double_degenerate", 0)))
    if svg:
        limit = max((c["report"]["options"]["time_limit"] for c in cases if c["report"]), default=120)
        cumulative_svg(cases, svg, limit)
        print("\nwrote %s" % svg)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
