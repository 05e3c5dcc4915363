#!/usr/bin/env python3
# The race's report (tools/race_cycles.sh): each renderer's error against its own reference
# (the mean of two independent halves, seeds >= 100; their noise, a quarter of the halves'
# difference, subtracted), mean seconds and error per sample count over the seeds, and the
# time each renderer needs to reach the error Cycles has after 256 samples (log-log
# interpolation between the measured counts; beyond them, error ~ 1 / time). One Cycles count
# can be off by 2x from a firefly, so the target is Cycles' fitted error at its 256-sample time:
# Cycles learns nothing, so its error * seconds is one constant, fitted as the geometric mean.
# usage: race_report.py RESULTS.jsonl
import array
import json
import math
import sys
from collections import defaultdict


def read_pfm(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise SystemExit(f"race_report: {path} is not an RGB PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        pixels = array.array("f")
        pixels.frombytes(f.read(width * height * 12))
    if scale > 0:  # big-endian
        pixels.byteswap()
    return pixels


def rel_mse(image, reference):
    # The bench's measure: mean over pixels and channels of (x - r)^2 / (r^2 + 0.01).
    return sum((x - r) ** 2 / (r * r + 0.01) for x, r in zip(image, reference)) / len(reference)


def mean_luminance(rgb):
    n = len(rgb) // 3
    return sum(0.2126 * rgb[3 * i] + 0.7152 * rgb[3 * i + 1] + 0.0722 * rgb[3 * i + 2]
               for i in range(n)) / n


def time_to_error(curve, target):
    # curve: [(seconds, error)] by increasing seconds; the seconds at which error == target.
    for (t0, e0), (t1, e1) in zip(curve, curve[1:]):
        if e1 <= target <= e0 and e0 > e1 > 0:
            f = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0))), False
    t, e = curve[-1] if target < curve[-1][1] else curve[0]
    return t * e / target, True  # extrapolated


def error_at_time(curve, seconds):
    # log-log interpolation of the error at a time inside the measured range, else None.
    for (t0, e0), (t1, e1) in zip(curve, curve[1:]):
        if t0 <= seconds <= t1 and e0 > 0 and e1 > 0:
            f = (math.log(seconds) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp(math.log(e0) + f * (math.log(e1) - math.log(e0)))
    return None


def main():
    rows = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
    references = defaultdict(list)
    tests = defaultdict(list)
    for r in rows:
        key = "qlight_off" if r["renderer"].startswith("qlight") else r["renderer"]
        if r["result"]["seed"] >= 100:
            references[key].append(read_pfm(r["image"]))
        else:
            tests[r["renderer"]].append(r)

    out = []
    reference_of, noise_of = {}, {}
    out.append("| reference | samples | mean luminance | noise (relMSE) |")
    out.append("| --- | ---: | ---: | ---: |")
    for key, halves in sorted(references.items()):
        a, b = halves
        ref = array.array("f", ((x + y) * 0.5 for x, y in zip(a, b)))
        # Var of the mean of two halves = E[(a - b)^2] / 4, relative to the mean.
        noise = sum((x - y) ** 2 / (r * r + 0.01) for x, y, r in zip(a, b, ref)) / len(ref) / 4
        reference_of[key], noise_of[key] = ref, noise
        spp = [r["result"]["spp"] for r in rows if r["result"]["seed"] >= 100 and
               (r["renderer"] == key or (key == "qlight_off" and r["renderer"].startswith("qlight")))]
        out.append(f"| {key} | {sum(spp)} | {mean_luminance(ref):.5f} | {noise:.4f} |")
    if len(reference_of) == 2:
        # The two renderers must render the same scene: their long references' means agree
        # (Cycles' two-sided mesh emission once made its Cornell box 6% brighter).
        ratio = mean_luminance(reference_of["qlight_off"]) / mean_luminance(reference_of["cycles"])
        out.append("")
        out.append(f"qlight's reference mean over Cycles': {ratio:.4f}.")
    out.append("")

    curves = {}
    out.append("| renderer | samples | seconds (mean of seeds) | relMSE, reference noise removed |")
    out.append("| --- | ---: | ---: | ---: |")
    for name, renders in sorted(tests.items()):
        key = "qlight_off" if name.startswith("qlight") else name
        by_spp = defaultdict(list)
        for r in renders:
            err = rel_mse(read_pfm(r["image"]), reference_of[key]) - noise_of[key]
            by_spp[r["result"]["spp"]].append((r["result"]["seconds"], err))
        curve = []
        for spp in sorted(by_spp):
            seconds = sum(s for s, _ in by_spp[spp]) / len(by_spp[spp])
            err = sum(e for _, e in by_spp[spp]) / len(by_spp[spp])
            curve.append((seconds, err))
            out.append(f"| {name} | {spp} | {seconds:.2f} | {err:.4f} |")
        curves[name] = (curve, dict((spp, c) for spp, c in zip(sorted(by_spp), curve)))
    out.append("")

    cycles_curve, cycles_by_spp = curves["cycles"]
    cycles_256 = cycles_by_spp.get(256)
    if cycles_256:
        t_c, e_measured = cycles_256
        inefficiency = math.exp(sum(math.log(t * e) for t, e in cycles_curve) / len(cycles_curve))
        e_c = inefficiency / t_c
        out.append(f"Cycles after 256 samples: {t_c:.2f} s, relMSE {e_measured:.4f} measured, "
                   f"{e_c:.4f} fitted (error * seconds = {inefficiency:.3f} over all its counts).")
        out.append("")
        out.append("| renderer | seconds to Cycles' fitted 256-sample error | vs Cycles |")
        out.append("| --- | ---: | ---: |")
        for name, (curve, _) in sorted(curves.items()):
            if name == "cycles":
                continue
            t, extrapolated = time_to_error(curve, e_c)
            note = " (extrapolated)" if extrapolated else ""
            out.append(f"| {name} | {t:.2f}{note} | {t / t_c:.2f}x |")
        out.append("")
        # Beyond Cycles' longest render its fit (error * seconds constant) stands in, marked *.
        longest = max(c[0][-1][0] for c in curves.values())
        times = [t for t, _ in cycles_curve] + [t for t in (60.0, 120.0) if t <= longest]
        out.append("Error at equal time, as a fraction of Cycles' fitted error at that time "
                   "(* beyond Cycles' longest render):")
        out.append("")
        out.append("| renderer | " + " | ".join(
            f"{t:.1f} s" + ("*" if t > cycles_curve[-1][0] else "") for t in times) + " |")
        out.append("| --- |" + " ---: |" * len(times))
        for name, (curve, _) in sorted(curves.items()):
            if name == "cycles":
                continue
            cells = []
            for t in times:
                e = error_at_time(curve, t)
                cells.append("-" if e is None else f"{e * t / inefficiency:.2f}")
            out.append(f"| {name} | " + " | ".join(cells) + " |")
    print("\n".join(out))


main()
