#!/usr/bin/python3
"""The figures of the two sweep studies (papers/benchmarks/sweeps.md), from the rows `soma sweep` wrote.

  /usr/bin/python3 examples/sweeps/plot_sweeps.py cusp-map out/cusp_map/rows.csv out/cusp_map.png
  /usr/bin/python3 examples/sweeps/plot_sweeps.py real-counts out/random_6r/rows.csv out/random_6r.png

Needs Debian's python3-matplotlib (not part of the build or of CI).
"""
import csv
import sys
from collections import Counter

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import BoundaryNorm, ListedColormap  # noqa: E402


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def cusp_map(src, png):
    r = [x for x in rows(src) if x["status"] == "ok"]
    a2 = sorted({float(x["a2"]) for x in r})
    a3 = sorted({float(x["a3"]) for x in r})
    grid = [[float("nan")] * len(a2) for _ in a3]
    for x in r:
        grid[a3.index(float(x["a3"]))][a2.index(float(x["a2"]))] = int(x["cusps"])
    counts = Counter(int(x["cusps"]) for x in r)
    colours = ListedColormap(["#f0f0f0", "#9ecae1", "#fdae6b", "#3182bd", "#e6550d", "#31a354"])
    norm = BoundaryNorm([-0.5, 0.5, 1.5, 2.5, 3.5, 4.5, 5.5], colours.N)
    fig, ax = plt.subplots(figsize=(7.5, 5.5), dpi=130)
    # Cell edges halfway between the sample values.
    def edges(v):
        h = [(v[i] + v[i + 1]) / 2 for i in range(len(v) - 1)]
        return [v[0] - (h[0] - v[0])] + h + [v[-1] + (v[-1] - h[-1])]
    m = ax.pcolormesh(edges(a2), edges(a3), grid, cmap=colours, norm=norm, shading="flat")
    cb = fig.colorbar(m, ax=ax, ticks=[0, 1, 2, 3, 4, 5])
    cb.set_label("cusp points of the workspace section")
    ax.plot([2.0], [1.5], marker="*", color="black", markersize=12, linestyle="none",
            label="Wenger's arm (1, 2, 1.5, 1, 0): 4 cusps")
    ax.plot([0.2, 3.0], [0.2, 3.0], color="black", linewidth=0.8, linestyle="--", label="a3 = a2")
    ax.set_xlabel("a2 = d3 (Wenger's notation)")
    ax.set_ylabel("a3 = d4")
    n = len(r)
    ax.set_title("Orthogonal 3R arms (1, a2, a3, r2 = 1, r3 = 0): {} arms, ".format(n) +
                 ", ".join("{} with {}".format(counts[c], c) for c in sorted(counts)), fontsize=9)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(png)


def real_counts(src, png):
    r = rows(src)
    ok = [x for x in r if x["status"] == "ok"]
    counts = Counter(int(x["real"]) for x in ok)
    failed = len(r) - len(ok)
    fig, ax = plt.subplots(figsize=(7.5, 4.5), dpi=130)
    ks = list(range(0, 17))
    ax.bar(ks, [counts.get(k, 0) for k in ks], color=["#3182bd" if k % 2 == 0 else "#e6550d" for k in ks])
    for k in ks:
        if counts.get(k, 0):
            ax.text(k, counts[k], str(counts[k]), ha="center", va="bottom", fontsize=8)
    ax.set_xticks(ks)
    ax.set_xlabel("real postures (of 16 complex)")
    ax.set_ylabel("robots")
    ax.set_title("Random 6R robots at one pose: {} robots, {} not ok".format(len(r), failed), fontsize=9)
    fig.tight_layout()
    fig.savefig(png)


if __name__ == "__main__":
    {"cusp-map": cusp_map, "real-counts": real_counts}[sys.argv[1]](sys.argv[2], sys.argv[3])
