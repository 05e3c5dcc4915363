#!/usr/bin/env python3
"""Draws the plots and writes the report of a `qlight bench` run.

Usage: python3 tools/bench_report.py OUTDIR

Input (written by `qlight bench`, all paths relative to OUTDIR):
  OUTDIR/bench.json   run settings, per scene: reference, methods (checkpoints,
                      per-frame statistics, GPU time per pass, final figures),
                      headline ratios against the unguided method; optional
                      ray traversal comparison against Embree.
  OUTDIR/images/...   the reference and each method's final image as PFM.
Any figure may be null (not measured); such points are skipped and tables
show "n/a".

Output:
  OUTDIR/plots/<scene>_relmse_time.png   relMSE vs render time (log-log)
  OUTDIR/plots/<scene>_relmse_spp.png    relMSE vs samples per pixel (log-log)
  OUTDIR/plots/<scene>_emitter_hits.png  emitter hit share and mean path length per frame
  OUTDIR/plots/<scene>_gpu_passes.png    GPU ms per frame by pass category
  OUTDIR/plots/<scene>_images.png        final images and relative error maps
  OUTDIR/plots/traversal.png             Mrays/s, qlight vs Embree (if measured)
  OUTDIR/report.md                       settings, tables and the plots above

A plot whose data are all missing is not drawn; the report says so.
Exit status: 0 when every file was written; 2 with one line on stderr for
bad input (no bench.json, malformed JSON, a missing or unreadable PFM);
1 when a file cannot be written or turns out missing or empty.
"""

import argparse
import json
import math
import os
import re
import sys
import textwrap

SYSTEM_PYTHON = "/usr/bin/python3"


class BadInput(Exception):
    """Input the report cannot be made from; the message names what is wrong."""


# numpy, matplotlib.pyplot and matplotlib.ticker, set by import_plotting().
np = plt = ticker = None


def import_plotting():
    """Imports numpy and matplotlib (Agg backend) into the module globals.

    Debian's python3-matplotlib lives in the system interpreter; when another
    python3 comes first on PATH (pyenv, a venv) without it, rerun this script
    with the system one.
    """
    global np, plt, ticker
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as pyplot
        import matplotlib.ticker as mticker
        import numpy
    except ImportError as e:
        if os.path.exists(SYSTEM_PYTHON) and os.path.realpath(sys.executable) != os.path.realpath(SYSTEM_PYTHON) \
                and not os.environ.get("BENCH_REPORT_REEXEC"):
            os.environ["BENCH_REPORT_REEXEC"] = "1"
            os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON] + sys.argv)
        raise BadInput(f"needs numpy and matplotlib ({e}; apt-get install python3-matplotlib python3-numpy)")
    np, plt, ticker = numpy, pyplot, mticker


# --------------------------------------------------------------------------- constants

# Fixed colours, so a method or a pass category looks the same in every plot.
METHOD_COLOURS = {
    "unguided": "#4d4d4d",
    "guided": "#1f77b4",
    "guided_light": "#d62728",
    "guided_frozen": "#2ca02c",
    "guided_dqn": "#9467bd",
}
SPARE_COLOURS = ["#9467bd", "#8c564b", "#e377c2", "#bcbd22", "#17becf", "#ff7f0e"]

# (category, colour, predicate on the pass name); the first match wins, "other" catches the rest.
PASS_CATEGORIES = [
    ("camera + queue", "#7f7f7f", lambda p: p in ("path.begin", "path.queue")),
    ("trace", "#1f77b4", lambda p: p == "path.trace"),
    ("shade (point search; fused: extension rays too)", "#ff7f0e", lambda p: p == "path.shade"),
    ("accumulate", "#bcbd22", lambda p: p in ("path.end", "stats.clear") or p.startswith("accumulate.")),
    ("Q update", "#2ca02c", lambda p: p == "guiding.q_update"),
    ("CDF scans", "#9467bd", lambda p: p.startswith("prefix_sum.")),
    ("light learning", "#d62728", lambda p: p == "guiding.v_update"),
    ("other", "#c7c7c7", lambda p: True),
]

BASELINE = "unguided"
RELMSE_EPSILON = 0.01      # relMSE = mean (x - ref)^2 / (ref^2 + 0.01)
ERROR_MAP_EPSILON = 0.01   # error map = |x - ref| / (ref + 0.01), on luminance
ERROR_MAP_MAX = 2.0
LAST_FRAMES_SHARE = 0.1    # emitter hit share is averaged over the last 10% of frames
SMOOTH_ABOVE_FRAMES = 200  # per-frame plots with more frames also draw a running mean


# --------------------------------------------------------------------------- small helpers

def num(value):
    """The value as a finite float, or None (null, NaN, inf, not a number)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    value = float(value)
    return value if math.isfinite(value) else None


def fmt(value, spec=".3g"):
    """A number for a table, "n/a" when missing."""
    value = num(value)
    return "n/a" if value is None else format(value, spec)


def as_dict(value):
    return value if isinstance(value, dict) else {}


def as_list(value):
    return value if isinstance(value, list) else []


def safe_name(name):
    """A scene name usable in a file name."""
    return re.sub(r"[^A-Za-z0-9_.-]", "_", str(name)) or "scene"


def method_label(method):
    return str(method.get("label") or method.get("name") or "?")


def method_colour(name, index):
    return METHOD_COLOURS.get(name, SPARE_COLOURS[index % len(SPARE_COLOURS)])


def with_unit(value, unit, spec=".3g"):
    """ "3 s", or "n/a" when missing."""
    text = fmt(value, spec)
    return text if text == "n/a" else f"{text} {unit}"


def wrap(text, width):
    return "\n".join(textwrap.wrap(text, width, break_on_hyphens=False)) or text


def plural(count, noun):
    """"1 light", "2 lights", "n/a lights"."""
    return f"{fmt(count, '.0f')} {noun}{'' if num(count) == 1 else 's'}"


def md_cell(text):
    """Text safe inside a markdown table cell."""
    return str(text).replace("|", "\\|").replace("\n", " ")


def find_baseline(scene):
    for m in scene["methods"]:
        if m.get("name") == BASELINE:
            return m
    return None


# --------------------------------------------------------------------------- input

def load_bench(outdir):
    """bench.json as a dict, its structure checked enough for the rest to rely on."""
    path = os.path.join(outdir, "bench.json")
    if not os.path.isdir(outdir):
        raise BadInput(f"{outdir}: no such folder")
    if not os.path.isfile(path):
        raise BadInput(f"{path}: missing")
    try:
        with open(path, encoding="utf-8") as f:
            bench = json.load(f)
    except (OSError, UnicodeDecodeError) as e:
        raise BadInput(f"{path}: cannot read ({e})")
    except json.JSONDecodeError as e:
        raise BadInput(f"{path}: malformed JSON ({e.msg} at line {e.lineno} column {e.colno})")
    check_structure(bench, path)
    return bench


def check_structure(bench, path):
    """Raises BadInput unless bench has a list of scenes, each with a name and a list of methods."""
    if not isinstance(bench, dict):
        raise BadInput(f"{path}: top level is not an object")
    if not isinstance(bench.get("scenes"), list):
        raise BadInput(f"{path}: no \"scenes\" list")
    for i, scene in enumerate(bench["scenes"]):
        if not isinstance(scene, dict) or not scene.get("name"):
            raise BadInput(f"{path}: scene {i} has no name")
        if not isinstance(scene.get("methods"), list) or not all(isinstance(m, dict) for m in scene["methods"]):
            raise BadInput(f"{path}: scene {scene['name']} has no \"methods\" list of objects")
        for key in ("reference", "headline"):
            if scene.get(key) is not None and not isinstance(scene[key], dict):
                raise BadInput(f"{path}: scene {scene['name']}: \"{key}\" is not an object")
    traversal = bench.get("traversal")
    if traversal is not None and not isinstance(traversal, dict):
        raise BadInput(f"{path}: \"traversal\" is neither null nor an object")


def read_pfm(path):
    """A colour PFM as a float32 array (height, width, 3), top row first."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise BadInput(f"{path}: cannot read ({e.strerror or e})")
    header = re.match(rb"(PF|Pf)\s+(\d+)\s+(\d+)\s+([-+0-9.eE]+)\s", data)
    if not header or header.group(1) != b"PF":
        raise BadInput(f"{path}: not a colour PFM")
    width, height, scale = int(header.group(2)), int(header.group(3)), float(header.group(4))
    count = width * height * 3
    if width == 0 or height == 0 or len(data) - header.end() < count * 4:
        raise BadInput(f"{path}: truncated PFM ({width}x{height})")
    dtype = "<f4" if scale < 0 else ">f4"
    pixels = np.frombuffer(data, dtype=dtype, count=count, offset=header.end()).astype(np.float32)
    return np.flipud(pixels.reshape(height, width, 3))  # PFM stores the bottom row first


def image_paths(scene):
    """[(what, path relative to OUTDIR or None)]: the reference first, then each method's final image."""
    paths = [(f"{scene['name']} reference", as_dict(scene.get("reference")).get("pfm"))]
    paths += [(f"{scene['name']} {m.get('name')}", as_dict(m.get("final")).get("pfm")) for m in scene["methods"]]
    return paths


def check_images_exist(bench, outdir):
    """Raises BadInput naming the first PFM that bench.json lists but OUTDIR lacks."""
    for scene in bench["scenes"]:
        for what, relpath in image_paths(scene):
            if relpath and not os.path.isfile(os.path.join(outdir, str(relpath))):
                raise BadInput(f"{os.path.join(outdir, str(relpath))}: missing ({what})")


def load_image(outdir, relpath):
    """The PFM at OUTDIR/relpath, or None when relpath is null (not written)."""
    return read_pfm(os.path.join(outdir, str(relpath))) if relpath else None


def load_scene_images(outdir, scene):
    """(reference or None, [method image or None]), sizes checked against the reference."""
    (_, ref_path), *method_paths = image_paths(scene)
    reference = load_image(outdir, ref_path)
    images = []
    for m, (_, relpath) in zip(scene["methods"], method_paths):
        img = load_image(outdir, relpath)
        if img is not None and reference is not None and img.shape != reference.shape:
            raise BadInput(f"{scene['name']} {m.get('name')}: image is {img.shape[1]}x{img.shape[0]}, "
                           f"reference {reference.shape[1]}x{reference.shape[0]}")
        images.append(img)
    return reference, images


# --------------------------------------------------------------------------- image maths

def tonemap(rgb):
    """Linear radiance -> display sRGB in [0, 1]: exposure 1, the ACES fit the renderer uses."""
    x = np.nan_to_num(np.maximum(rgb, 0.0), nan=0.0, posinf=1e6)
    mapped = np.clip(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0)
    return np.where(mapped <= 0.0031308, 12.92 * mapped, 1.055 * np.power(mapped, 1 / 2.4) - 0.055)


def luminance(rgb):
    return rgb[..., 0] * 0.2126 + rgb[..., 1] * 0.7152 + rgb[..., 2] * 0.0722


def relative_error_map(image, reference):
    """|L(x) - L(ref)| / (L(ref) + 0.01) per pixel, non-finite pixels at the top of the scale."""
    ref = luminance(reference)
    err = np.abs(luminance(image) - ref) / (np.abs(ref) + ERROR_MAP_EPSILON)
    return np.nan_to_num(err, nan=ERROR_MAP_MAX, posinf=ERROR_MAP_MAX)


def relative_mse(image, reference):
    """The bench's relMSE, for images whose figure bench.json lacks."""
    value = float(np.mean((image - reference) ** 2 / (reference ** 2 + RELMSE_EPSILON)))
    return value if math.isfinite(value) else None


# --------------------------------------------------------------------------- derived figures

def checkpoint_series(method, x_key):
    """(xs, relmse) of the method's checkpoints with both values positive (log axes)."""
    xs, ys = [], []
    for c in as_list(method.get("checkpoints")):
        x, y = num(as_dict(c).get(x_key)), num(as_dict(c).get("relmse"))
        if x is not None and y is not None and x > 0 and y > 0:
            xs.append(x)
            ys.append(y)
    return xs, ys


def frame_series(method, key):
    """(frame numbers from 1, values) with missing values left out."""
    values = as_list(as_dict(method.get("frames")).get(key))
    points = [(i + 1, num(v)) for i, v in enumerate(values)]
    return [i for i, v in points if v is not None], [v for _, v in points if v is not None]


def last_frames_mean(method, key):
    """Mean of `key` over the last 10% of frames (at least one), None when unmeasured."""
    values = as_list(as_dict(method.get("frames")).get(key))
    tail = values[len(values) - max(1, math.ceil(LAST_FRAMES_SHARE * len(values))):] if values else []
    tail = [v for v in map(num, tail) if v is not None]
    return sum(tail) / len(tail) if tail else None


def ratio(a, b):
    a, b = num(a), num(b)
    return a / b if a is not None and b not in (None, 0.0) else None


def pass_category(name):
    return next(cat for cat, _, matches in PASS_CATEGORIES if matches(name))


def gpu_ms_by_category(method):
    """{category: ms per frame} over the method's measured passes; empty when none."""
    totals = {}
    for name, ms in as_dict(method.get("gpu_ms_per_frame")).items():
        ms = num(ms)
        if ms is not None:
            cat = pass_category(str(name))
            totals[cat] = totals.get(cat, 0.0) + ms
    return totals


def final_value(method, key):
    return num(as_dict(method.get("final")).get(key))


# --------------------------------------------------------------------------- plots

def new_figure(width, height, rows=1, cols=1, **kwargs):
    return plt.subplots(rows, cols, figsize=(width, height), **kwargs)


def save_figure(fig, path, written):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    written.append(path)
    return path


def plot_methods_loglog(ax, scene, x_key):
    """One relMSE line per method against x_key; True when anything was drawn."""
    drawn = False
    for i, m in enumerate(scene["methods"]):
        xs, ys = checkpoint_series(m, x_key)
        if xs:
            ax.plot(xs, ys, marker="o", markersize=3, linewidth=1.5,
                    color=method_colour(m.get("name"), i), label=method_label(m))
            drawn = True
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    ax.set_ylabel("relMSE")
    return drawn


def label_log_axis(axis, limits):
    """On a log axis spanning under three decades, label 1-2-5 steps in plain numbers."""
    low, high = limits
    if low > 0 and high / low < 1e3:
        axis.set_major_locator(ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        axis.set_major_formatter(ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        axis.set_minor_formatter(ticker.NullFormatter())


def label_log_axes(ax):
    if ax.get_xscale() == "log":
        label_log_axis(ax.xaxis, ax.get_xlim())
    if ax.get_yscale() == "log":
        label_log_axis(ax.yaxis, ax.get_ylim())


def finish_legend(ax):
    ax.legend(fontsize=8, loc="best", framealpha=0.9)


def plot_relmse_time(scene, path, written):
    fig, ax = new_figure(7, 4.5)
    if not plot_methods_loglog(ax, scene, "seconds"):
        return close_empty(fig)
    baseline = find_baseline(scene)
    target = final_value(baseline, "relmse") if baseline else None
    if target and target > 0:
        ax.axhline(target, color=METHOD_COLOURS[BASELINE], linestyle="--", linewidth=1,
                   label=f"unguided final relMSE ({target:.3g})")
    reference = as_dict(scene.get("reference"))
    noise = num(reference.get("noise_relmse"))
    if noise and noise > 0:
        spp = num(reference.get("spp"))
        ax.axhline(noise, color="black", linestyle=":", linewidth=1,
                   label=f"reference noise ({fmt(spp, '.0f')} spp)")
    label_log_axes(ax)
    ax.set_xlabel("render time [s] (cumulative)")
    ax.set_title(f"{scene['name']}: relMSE vs render time")
    finish_legend(ax)
    fig.tight_layout()
    return save_figure(fig, path, written)


def plot_relmse_spp(scene, path, written):
    fig, ax = new_figure(7, 4.5)
    if not plot_methods_loglog(ax, scene, "spp"):
        return close_empty(fig)
    label_log_axes(ax)
    ax.set_xlabel("samples per pixel")
    ax.set_title(f"{scene['name']}: relMSE vs samples per pixel")
    finish_legend(ax)
    fig.tight_layout()
    return save_figure(fig, path, written)


def spans_decades(values):
    positive = [v for v in values if v > 0]
    return len(positive) == len(values) and bool(positive) and max(positive) / min(positive) > 10


def running_mean(values, window):
    """Mean over `window` values centred on each position (fewer at the ends)."""
    sums = np.cumsum(np.concatenate(([0.0], values)))
    index = np.arange(len(values))
    starts = np.maximum(index - window // 2, 0)
    ends = np.minimum(index + window - window // 2, len(values))
    return (sums[ends] - sums[starts]) / (ends - starts)


def smoothing_window(scene, key):
    """Frames per running mean for the panel: 1 (none) up to SMOOTH_ABOVE_FRAMES frames."""
    longest = max((len(frame_series(m, key)[0]) for m in scene["methods"]), default=0)
    return 1 if longest <= SMOOTH_ABOVE_FRAMES else max(2, longest // 50)


def plot_frame_panel(ax, scene, key, ylabel, allow_log):
    """One line per method of a per-frame statistic; True when anything was drawn.

    With many frames each method's raw series is drawn faintly under its running mean.
    """
    everything = []
    window = smoothing_window(scene, key)
    for i, m in enumerate(scene["methods"]):
        xs, ys = frame_series(m, key)
        if not xs:
            continue
        colour = method_colour(m.get("name"), i)
        if window > 1:
            ax.plot(xs, ys, linewidth=0.6, alpha=0.25, color=colour)
            ax.plot(xs, running_mean(ys, window), linewidth=1.4, color=colour, label=method_label(m))
        else:
            ax.plot(xs, ys, linewidth=1.2, color=colour, label=method_label(m))
        everything += ys
    if window > 1:
        ylabel += f"\n(line: mean over {window} frames)"
    if allow_log and spans_decades(everything):
        ax.set_yscale("log")
        label_log_axes(ax)
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", alpha=0.3)
    if not everything:
        ax.text(0.5, 0.5, "not measured", transform=ax.transAxes, ha="center", va="center", color="grey")
    return bool(everything)


def unique_handles(*axes):
    """{label: line} over the axes' lines, first occurrence kept."""
    handles = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, handle)
    return handles


def plot_emitter_hits(scene, path, written):
    fig, (top, bottom) = new_figure(7, 6, 2, 1, sharex=True)
    hits = plot_frame_panel(top, scene, "emitter_hit_share", "emitter hit share", True)
    lengths = plot_frame_panel(bottom, scene, "mean_path_length", "mean path length [vertices]", False)
    if not hits and not lengths:
        return close_empty(fig)
    top.set_title(f"{scene['name']}: paths per frame")
    bottom.set_xlabel("frame")
    handles = unique_handles(top, bottom)
    fig.legend(handles.values(), handles.keys(), fontsize=8, loc="lower center", ncol=2, frameon=False)
    legend_inches = 0.2 * math.ceil(len(handles) / 2) + 0.05
    fig.tight_layout(rect=(0, legend_inches / fig.get_figheight(), 1, 1))
    return save_figure(fig, path, written)


def plot_gpu_passes(scene, path, written):
    per_method = [gpu_ms_by_category(m) for m in scene["methods"]]
    if not any(per_method):
        return None
    fig, ax = new_figure(8, 4.8)
    x = np.arange(len(per_method))
    bottoms = np.zeros(len(per_method))
    for cat, colour, _ in PASS_CATEGORIES:
        heights = np.array([ms.get(cat, 0.0) for ms in per_method])
        if heights.any():
            ax.bar(x, heights, 0.6, bottom=bottoms, color=colour, label=cat, edgecolor="white", linewidth=0.5)
            bottoms += heights
    for xi, total, ms in zip(x, bottoms, per_method):
        ax.annotate(f"{total:.2f} ms" if ms else "n/a", (xi, total), xytext=(0, 3),
                    textcoords="offset points", ha="center", fontsize=8)
    ax.set_xticks(x, [wrap(method_label(m), 18) for m in scene["methods"]], fontsize=8)
    ax.set_ylabel("GPU ms per frame")
    ax.set_ylim(0, bottoms.max() * 1.12 or 1)
    ax.set_title(f"{scene['name']}: GPU time per frame by pass")
    handles, labels = ax.get_legend_handles_labels()
    ax.legend(handles[::-1], labels[::-1], fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
    fig.tight_layout()
    return save_figure(fig, path, written)


def image_title(label, relmse, width, computed):
    return f"{wrap(label, width)}\nrelMSE {fmt(relmse)}{' (from image)' if computed else ''}"


def plot_images(scene, reference, images, path, written):
    """Top row: reference and final images; bottom row: error maps with one colorbar."""
    if reference is None and not any(img is not None for img in images):
        return None
    columns = 1 + len(images)
    shape = (reference if reference is not None else next(i for i in images if i is not None)).shape
    panel_w = min(4.5, max(2.6, shape[1] / 120))  # inches; larger renders get larger panels
    panel_h = panel_w * shape[0] / shape[1]
    fig, axes = new_figure(panel_w * columns + 0.9, 2 * panel_h + 1.3, 2, columns, squeeze=False)
    for ax in axes.flat:
        ax.set_xticks([])
        ax.set_yticks([])
    ref_info = as_dict(scene.get("reference"))
    show_image(axes[0][0], reference, f"reference\n{fmt(ref_info.get('spp'), '.0f')} spp", shape)
    describe_error_map(axes[1][0], reference is not None)
    error_image = None
    width = max(14, int(panel_w * 8))
    for col, (m, img) in enumerate(zip(scene["methods"], images), start=1):
        relmse = final_value(m, "relmse")
        computed = relmse is None and img is not None and reference is not None
        if computed:
            relmse = relative_mse(img, reference)
        show_image(axes[0][col], img, image_title(method_label(m), relmse, width, computed), shape)
        if img is not None and reference is not None:
            error_image = axes[1][col].imshow(relative_error_map(img, reference), cmap="inferno",
                                              vmin=0, vmax=ERROR_MAP_MAX, interpolation="nearest")
        else:
            mark_missing(axes[1][col], shape)
    fig.suptitle(f"{scene['name']}: final images (ACES, exposure 1) and relative error", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1 - 0.7 / fig.get_figwidth(), 1))
    if error_image is not None:
        add_error_colorbar(fig, axes[1], error_image)
    return save_figure(fig, path, written)


def show_image(ax, image, title, shape):
    if image is None:
        mark_missing(ax, shape)
    else:
        ax.imshow(tonemap(image), interpolation="nearest")
    ax.set_title(title, fontsize=8)


def mark_missing(ax, shape):
    """A "no image" panel the size of an image of `shape`."""
    ax.set_xlim(0, shape[1])
    ax.set_ylim(shape[0], 0)
    ax.set_aspect("equal")
    ax.text(0.5, 0.5, "no image", transform=ax.transAxes, ha="center", va="center", color="grey")


def describe_error_map(ax, has_reference):
    ax.axis("off")
    text = ("relative error\n|x - ref| / (ref + 0.01)\n(luminance),\nclipped to [0, 2]"
            if has_reference else "no reference:\nno error maps")
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", fontsize=8)


def add_error_colorbar(fig, row_axes, mappable):
    """A colorbar to the right of the error-map row, as tall as the row."""
    right = max(ax.get_position().x1 for ax in row_axes)
    box = row_axes[-1].get_position()
    cax = fig.add_axes([right + 0.01, box.y0, 0.012, box.height])
    fig.colorbar(mappable, cax=cax).ax.tick_params(labelsize=7)


def close_empty(fig):
    plt.close(fig)
    return None


def traversal_rows(traversal):
    """[(scene, triangles, kind entry)] over the traversal comparison."""
    rows = []
    for s in as_list(as_dict(traversal).get("scenes")):
        s = as_dict(s)
        for k in as_list(s.get("kinds")):
            if isinstance(k, dict):
                rows.append((str(s.get("scene", "?")), s.get("triangles"), k))
    return rows


def plot_traversal(traversal, path, written):
    rows = traversal_rows(traversal)
    values = [(num(k.get("qlight_mrays")), num(k.get("embree_mrays"))) for _, _, k in rows]
    if not any(v is not None and v > 0 for pair in values for v in pair):
        return None
    fig, ax = new_figure(max(6, 1.1 * len(rows) + 2), 4.8)
    x = np.arange(len(rows))
    for offset, index, name, colour in ((-0.2, 0, "qlight", "#1f77b4"), (0.2, 1, "Embree", "#7f7f7f")):
        heights = [v[index] if v[index] and v[index] > 0 else np.nan for v in values]
        ax.bar(x + offset, heights, 0.4, label=name, color=colour)
    for xi, (_, _, k), (q, e) in zip(x, rows, values):
        r = num(k.get("ratio"))
        if r is None:
            r = ratio(q, e)
        top = max([v for v in (q, e) if v and v > 0], default=None)
        if top:
            ax.annotate("n/a" if r is None else f"{r:.2f}x", (xi, top), xytext=(0, 3), textcoords="offset points",
                        ha="center", fontsize=8)
    ax.set_yscale("log")
    measured = [v for pair in values for v in pair if v is not None and v > 0]
    ax.set_ylim(10 ** math.floor(math.log10(min(measured))), max(measured) * 1.6)  # bars start at a decade
    label_log_axes(ax)
    ax.set_xticks(x, [f"{wrap(scene, 14)}\n{k.get('kind', '?')}" for scene, _, k in rows], fontsize=8)
    ax.set_ylabel("Mrays/s")
    ax.set_title("Ray traversal: qlight vs Embree (annotation: qlight / Embree)")
    ax.grid(True, axis="y", which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return save_figure(fig, path, written)


# --------------------------------------------------------------------------- report

def run_description(bench):
    """The bullet list saying what was run."""
    width, height = bench.get("width"), bench.get("height")
    items = [
        ("mode", bench.get("mode")),
        ("device", bench.get("device")),
        ("resolution", f"{fmt(width, '.0f')} x {fmt(height, '.0f')}"),
        ("samples per pixel per frame", fmt(bench.get("spp_per_frame"), ".0f")),
        ("time budget per method", with_unit(bench.get("time_budget_seconds"), "s")),
        ("reference samples per pixel", fmt(bench.get("reference_spp"), ".0f")),
        ("renderer version", bench.get("renderer_version")),
        ("date", bench.get("date")),
        ("scenes", ", ".join(str(s["name"]) for s in bench["scenes"]) or "none"),
    ]
    settings = bench.get("settings")
    if isinstance(settings, dict) and settings:
        items.append(("renderer and guiding settings",
                      ", ".join(f"{key} {value}" for key, value in settings.items())))
    return [f"- {name}: {value if value not in (None, '') else 'n/a'}" for name, value in items]


HOW_TO_READ = (
    "relMSE is the mean over pixels and RGB channels of (x - ref)^2 / (ref^2 + 0.01), "
    "measured against the scene's reference image. Every method renders for the same time budget. "
    "\"Time to unguided's error\" is the time from which a method's relMSE stays at or below the "
    "unguided method's final relMSE, divided by the unguided method's render time: a value below 1 "
    "means the method reaches that error sooner; \"(extrapolated)\" marks methods that did not reach it within the budget, "
    "whose time is extrapolated from their last checkpoint with relMSE ~ 1/t. "
    "\"Equal-spp relMSE ratio\" is the method's relMSE divided by the unguided relMSE at the same "
    "samples per pixel (below 1: lower error per sample). \"Time per sample ratio\" is the method's "
    "ms per sample per pixel divided by the unguided one's (above 1: each sample costs more). "
    "The emitter hit share is the share of paths that hit an emitter, averaged over the last 10% "
    "of frames and divided by the unguided method's."
)


def headline_value(scene, key, method_name):
    return as_dict(as_dict(scene.get("headline")).get(key)).get(method_name)


def time_to_error_cell(scene, method_name):
    value = headline_value(scene, "time_to_unguided_error", method_name)
    text = fmt(value, ".2f")
    if text != "n/a" and headline_value(scene, "time_to_unguided_error_extrapolated", method_name) is True:
        text += " (extrapolated)"
    return text


def markdown_table(header, rows, text_columns=1):
    """A markdown table; the first text_columns are left-aligned, the numbers right-aligned."""
    lines = ["| " + " | ".join(md_cell(h) for h in header) + " |",
             "|" + "|".join("---" if i < text_columns else "---:" for i in range(len(header))) + "|"]
    lines += ["| " + " | ".join(md_cell(c) for c in row) + " |" for row in rows]
    return lines


def summary_table(scene):
    """The headline figures, one row per method."""
    baseline = find_baseline(scene)
    base_hits = last_frames_mean(baseline, "emitter_hit_share") if baseline else None
    header = ["method", "time to unguided's error", "equal-spp relMSE ratio",
              "same, reference noise removed", "time per sample ratio",
              "final relMSE", "emitter hit share (last 10%) / unguided", "guide memory [MiB]"]
    rows = []
    for m in scene["methods"]:
        name = m.get("name")
        is_base = m is baseline
        memory = num(m.get("guide_memory_bytes"))
        rows.append([
            method_label(m),
            "baseline" if is_base else time_to_error_cell(scene, name),
            "baseline" if is_base else fmt(headline_value(scene, "equal_spp_relmse_ratio", name), ".2f"),
            "baseline" if is_base else fmt(headline_value(
                scene, "equal_spp_relmse_ratio_without_reference_noise", name), ".2f"),
            "baseline" if is_base else fmt(headline_value(scene, "time_per_sample_ratio", name), ".2f"),
            fmt(final_value(m, "relmse")),
            fmt(ratio(last_frames_mean(m, "emitter_hit_share"), base_hits), ".2f"),
            fmt(memory / 2 ** 20 if memory is not None else None, ".2f"),
        ])
    return markdown_table(header, rows)


def final_table(scene):
    """The final figures behind the headline, one row per method."""
    header = ["method", "spp", "seconds", "ms per spp", "Mrays/s", "equal-spp relMSE", "cache points"]
    rows = []
    for m in scene["methods"]:
        equal = as_dict(m.get("equal_spp"))
        rays = final_value(m, "rays_per_second")
        rows.append([
            method_label(m),
            fmt(final_value(m, "spp"), ".0f"),
            fmt(final_value(m, "seconds"), ".2f"),
            fmt(final_value(m, "ms_per_spp"), ".3g"),
            fmt(rays / 1e6 if rays is not None else None, ".3g"),
            f"{fmt(equal.get('relmse'))} at {fmt(equal.get('spp'), '.0f')} spp",
            fmt(m.get("points"), ".0f"),
        ])
    return markdown_table(header, rows)


def reference_line(scene):
    ref = as_dict(scene.get("reference"))
    cached = {True: " (cached)", False: ""}.get(ref.get("cached"), "")
    return (f"Scene file {scene.get('file') or 'n/a'}, {plural(scene.get('triangles'), 'triangle')}, "
            f"{plural(scene.get('lights'), 'light')}. Reference: {fmt(ref.get('spp'), '.0f')} spp, "
            f"{with_unit(ref.get('seconds'), 's')}{cached}, estimated noise relMSE {fmt(ref.get('noise_relmse'))}.")


PLOT_KINDS = [
    ("relmse_time", "relMSE vs render time"),
    ("relmse_spp", "relMSE vs samples per pixel"),
    ("emitter_hits", "emitter hit share and mean path length per frame"),
    ("gpu_passes", "GPU time per frame by pass"),
    ("images", "final images and relative error maps"),
]


def scene_section(scene, plots, outdir):
    """The report's section of one scene: reference line, tables, plots."""
    lines = [f"## {scene['name']}", "", reference_line(scene), ""]
    if not scene["methods"]:
        return lines + ["No methods were run.", ""]
    lines += ["Headline figures (ratios against the unguided method):", "", *summary_table(scene), "",
              "Final figures at the end of the time budget:", "", *final_table(scene), ""]
    for kind, title in PLOT_KINDS:
        path = plots.get(kind)
        if path:
            alt = re.sub(r"[\[\]]", "", f"{scene['name']}: {title}")
            lines += [f"![{alt}]({os.path.relpath(path, outdir)})", ""]
        else:
            lines += [f"{title}: not measured.", ""]
    return lines


def traversal_section(traversal, plot_path, outdir):
    header = ["scene", "triangles", "ray kind", "qlight Mrays/s", "Embree Mrays/s", "qlight / Embree",
              "mismatches", "rays"]
    rows = [[scene, fmt(tris, ".0f"), k.get("kind", "?"), fmt(k.get("qlight_mrays")), fmt(k.get("embree_mrays")),
             fmt(k.get("ratio") if num(k.get("ratio")) is not None
                 else ratio(k.get("qlight_mrays"), k.get("embree_mrays")), ".2f"),
             fmt(k.get("mismatches"), ".0f"), fmt(k.get("rays"), ".0f")]
            for scene, tris, k in traversal_rows(traversal)]
    rows = [[r[0], r[2], r[1], *r[3:]] for r in rows]  # text columns first
    header = [header[0], header[2], header[1], *header[3:]]
    lines = ["## Ray traversal: qlight vs Embree", "", *markdown_table(header, rows, text_columns=2), ""]
    if plot_path:
        lines += [f"![ray traversal]({os.path.relpath(plot_path, outdir)})", ""]
    return lines


def write_report(bench, scene_plots, traversal_plot, outdir, written):
    lines = ["# qlight bench report", "", "## What was run", "", *run_description(bench), "",
             "## How to read this", "", HOW_TO_READ, ""]
    for scene, plots in zip(bench["scenes"], scene_plots):
        lines += scene_section(scene, plots, outdir)
    if bench.get("traversal") is not None:
        lines += traversal_section(bench["traversal"], traversal_plot, outdir)
    path = os.path.join(outdir, "report.md")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines).rstrip() + "\n")
    written.append(path)


# --------------------------------------------------------------------------- main

def draw_scene_plots(scene, outdir, written):
    """{plot kind: path or None} for one scene."""
    reference, images = load_scene_images(outdir, scene)
    base = os.path.join(outdir, "plots", safe_name(scene["name"]) + "_")
    return {
        "relmse_time": plot_relmse_time(scene, base + "relmse_time.png", written),
        "relmse_spp": plot_relmse_spp(scene, base + "relmse_spp.png", written),
        "emitter_hits": plot_emitter_hits(scene, base + "emitter_hits.png", written),
        "gpu_passes": plot_gpu_passes(scene, base + "gpu_passes.png", written),
        "images": plot_images(scene, reference, images, base + "images.png", written),
    }


def check_written(written):
    """Names the first written file that is missing or empty, None when all are there."""
    for path in written:
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            return path
    return None


def make_report(outdir):
    """Draws every plot and writes report.md; returns the paths written."""
    bench = load_bench(outdir)
    check_images_exist(bench, outdir)  # before anything is written
    written = []
    scene_plots = [draw_scene_plots(scene, outdir, written) for scene in bench["scenes"]]
    traversal_plot = None
    if bench.get("traversal") is not None:
        traversal_plot = plot_traversal(bench["traversal"], os.path.join(outdir, "plots", "traversal.png"), written)
    write_report(bench, scene_plots, traversal_plot, outdir, written)
    return written


def main():
    parser = argparse.ArgumentParser(description="Plots and report of a qlight bench run.")
    parser.add_argument("outdir", help="the bench's output folder (holds bench.json)")
    args = parser.parse_args()
    try:
        import_plotting()
        written = make_report(args.outdir)
    except BadInput as e:
        print(f"bench_report.py: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"bench_report.py: cannot write {e.filename or args.outdir}: {e.strerror or e}", file=sys.stderr)
        return 1
    bad = check_written(written)
    if bad:
        print(f"bench_report.py: {bad}: missing or empty after writing", file=sys.stderr)
        return 1
    print(f"bench_report.py: wrote {os.path.join(args.outdir, 'report.md')} and {len(written) - 1} plots")
    return 0


if __name__ == "__main__":
    sys.exit(main())
