#!/usr/bin/env python3
"""Plots and tabulates `qlight bench --tracking`: OUT/tracking.json -> OUT/tracking.png, OUT/tracking.md.

Per case (a jumping and a moving light), the per-frame relative MSE of each method (the mean over
its seeds, drawn as the trailing mean the recovery is judged on), the jumps marked; the table gives
the frames each method needs after a jump to come back within 1.25x of the steady level, and its
mean error against unguided's.
"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"tracking": "tab:blue", "remember_all": "tab:orange", "unguided": "tab:gray",
           "unguided_other_seeds": "silver"}


def trailing_mean(values, window, jumps):
    out = []
    for f in range(len(values)):
        start = max([f + 1 - window, 0] + [j for j in jumps if j <= f])
        chunk = values[start:f + 1]
        out.append(sum(chunk) / len(chunk))
    return out


def fmt(v, digits=2):
    return "n/a" if v is None else f"{v:.{digits}f}"


def main(out_dir):
    out = Path(out_dir)
    data = json.loads((out / "tracking.json").read_text())
    cases = data["cases"]
    fig, axes = plt.subplots(1, len(cases), figsize=(6.2 * len(cases), 3.8), squeeze=False)
    for ax, case in zip(axes[0], cases):
        for m in case["methods"]:
            y = trailing_mean(m["rel_mse"], data["smooth_frames"], case["jump_frames"])
            ax.plot(range(len(y)), y, label=m["label"], color=COLOURS.get(m["name"]), lw=1.4)
        for j in case["jump_frames"]:
            ax.axvline(j, color="black", lw=0.8, ls=":")
        ax.set_yscale("log")
        ax.set_xlabel(f"frame ({data['fps']:g} per second of scene time)")
        ax.set_ylabel(f"relMSE of the frame (mean of {data['seeds']} seeds)")
        ax.set_title(f"{case['name']}: {case['what']}", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.suptitle(f"Tracking: {data['width']}x{data['height']}, {data['spp_per_frame']} spp per frame, "
                 f"trailing mean of {data['smooth_frames']} frames", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "tracking.png", dpi=110)

    lines = [f"# Tracking study ({data['device']})", "",
             f"{data['width']}x{data['height']}, {data['spp_per_frame']} spp per frame, "
             f"{data['seeds']} seeds, {data['frames']} frames at {data['fps']:g} per second of "
             f"scene time, references {data['reference_spp']} spp per light position. "
             f"Steady level: the tracking method's mean over the {data['steady_frames']} frames "
             f"before the next jump; back: the trailing mean of {data['smooth_frames']} frames "
             f"within 1.25x of it. Means and worst ratios after the first "
             f"{data['warmup_frames']} frames.", "",
             "| case | method | mean relMSE | vs unguided | worst vs unguided | back after each jump (frames) |",
             "| --- | --- | ---: | ---: | ---: | --- |"]
    for case in cases:
        for m in case["methods"]:
            backs = ", ".join(
                f"frame {r['jump_frame']}: {'not within the segment' if r['frames_to_within_1_25'] is None else r['frames_to_within_1_25']}"
                for r in m["recovery"]) or "(no jumps)"
            lines.append(f"| {case['name']} | {m['label']} | {fmt(m['mean_rel_mse'], 3)} | "
                         f"{fmt(m['mean_ratio_to_unguided'])} | "
                         f"{fmt(m['worst_smoothed_ratio_to_unguided'])} | {backs} |")
    lines += ["", "![tracking](tracking.png)", ""]
    (out / "tracking.md").write_text("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1])
