#!/usr/bin/env python3
"""Turn Google Benchmark JSON (soma's bench_* executables) into markdown tables of medians.

Usage:
  bench_table.py [--out FILE] [--load TEXT] [--time cpu|real] RESULT.json [RESULT.json ...]

Each JSON is the output of a bench_* executable run with
  --benchmark_format=json --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
Benchmark names are "<operation>/soma/<scalar>" or "<operation>/KDL/<call>"; a benchmark's label
says what the KDL call really computes, and the counter max_err is its largest error against
the 256-bit mpfr result of the same inputs (measured before timing).

With --out, the tables replace the text between the markers
  <!-- bench:begin --> and <!-- bench:end -->
of FILE, so hand-written notes outside the markers survive a regeneration; a missing file (or
one without markers) gets a title, the markers and the tables. Without --out: print to stdout.
Python 3 standard library only.
"""
import argparse
import json
import math
import os
import platform
import re
import sys

BEGIN = "<!-- bench:begin -->"
END = "<!-- bench:end -->"
SCALARS = ["float", "double", "long-double", "float128", "mpfr256"]
SCALAR_TITLES = {
    "float": "float",
    "double": "double",
    "long-double": "long double",
    "float128": "__float128",
    "mpfr256": "mpfr 256-bit",
}
UNIT_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def load_runs(paths, time_field):
    """Medians (ns), cv, max_err and label per benchmark, plus the context of each file."""
    runs, contexts = {}, []
    for path in paths:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        contexts.append(data.get("context", {}))
        for b in data.get("benchmarks", []):
            if b.get("run_type") != "aggregate":
                continue
            name = b["run_name"]
            r = runs.setdefault(name, {"order": len(runs)})
            agg = b.get("aggregate_name")
            if agg == "median":
                r["ns"] = b[time_field] * UNIT_NS[b.get("time_unit", "ns")]
                r["reps"] = b.get("repetitions")
                if "max_err" in b:
                    r["max_err"] = b["max_err"]
                if "label" in b:
                    r["label"] = b["label"]
            elif agg == "cv":
                r["cv"] = b[time_field]
    if not runs:
        sys.exit("bench_table: no aggregate results found (run with --benchmark_repetitions=N "
                 "--benchmark_report_aggregates_only=true)")
    return runs, contexts


def split(name):
    parts = name.split("/", 2)
    if len(parts) != 3:
        return None
    return parts[0], parts[1], parts[2]


def fmt_ns(x):
    if x is None:
        return "—"
    if x >= 100:
        return f"{x:,.0f} ns"
    if x >= 10:
        return f"{x:.1f} ns"
    return f"{x:.2f} ns"


def fmt_ratio(x):
    if x is None or not math.isfinite(x):
        return "—"
    if x >= 100:
        return f"{x:,.0f}×"
    if x >= 10:
        return f"{x:.1f}×"
    return f"{x:.2f}×"


def fmt_err(x):
    if x is None:
        return "—"
    if x == 0:
        return "0"
    return f"{x:.1e}"


def md_cell(text):
    """Text safe inside a markdown table cell."""
    return text.replace("|", "\\|")


def cpu_model():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def header(contexts, load, time_field, reps, flags):
    c = contexts[0]
    dates = sorted({x.get("date", "?") for x in contexts})
    loads = "; ".join(
        f"{os.path.basename(x.get('executable', '?'))}: "
        + ", ".join(f"{v:.2f}" for v in x.get("load_avg", []))
        for x in contexts)
    lines = [
        "| | |",
        "|---|---|",
        f"| date | {dates[0]}" + (f" … {dates[-1]}" if len(dates) > 1 else "") + " |",
        f"| machine | {cpu_model()}, {c.get('num_cpus', '?')} CPUs at {c.get('mhz_per_cpu', '?')} MHz"
        f" ({platform.system()} {platform.release()}), shared with other builds |",
        f"| load average (1, 5, 15 min) when each binary started | {loads} |",
    ]
    if load:
        lines.append(f"| load average around the whole run (uptime) | {load} |")
    lines += [
        f"| compiler | {c.get('soma_compiler', '?')} |",
        f"| compiler flags | `{c.get('soma_cxx_flags', '?')}` |",
        f"| libraries | Eigen {c.get('soma_eigen', '?')}, Orocos KDL {c.get('soma_kdl', '?')}, "
        f"mpfr at {c.get('soma_mpfr_bits', '?')} bits, Google Benchmark (library build type "
        f"{c.get('library_build_type', '?')}) |",
        f"| statistic | median over {reps} repetitions of the "
        f"{'per-thread CPU' if time_field == 'cpu_time' else 'wall-clock'} time per call |",
        f"| benchmark flags | `{flags}` |",
        f"| inputs | {c.get('soma_pool', '?')} fixed-seed random inputs (seed "
        f"{c.get('soma_seed', '?')}) prepared before timing and cycled; results kept with "
        "`benchmark::DoNotOptimize` |",
    ]
    return "\n".join(lines)


def ladder_table(runs, ops):
    out = [
        "Time per call (median) and, in brackets, the ratio to soma double:",
        "",
        "| operation | " + " | ".join(SCALAR_TITLES[s] for s in SCALARS) + " |",
        "|---|" + "---:|" * len(SCALARS),
    ]
    for op in ops:
        base = runs.get(f"{op}/soma/double", {}).get("ns")
        cells = []
        for s in SCALARS:
            r = runs.get(f"{op}/soma/{s}")
            if not r or "ns" not in r:
                cells.append("—")
                continue
            ratio = r["ns"] / base if base else None
            cells.append(f"{fmt_ns(r['ns'])} ({fmt_ratio(ratio)})")
        out.append(f"| {op} | " + " | ".join(cells) + " |")
    out += [
        "",
        "Largest error over the inputs against the 256-bit mpfr result of the same input "
        "(max-norm of the difference of the 4×4 matrix, twist or point; the inputs are the same "
        "double draws cast to each type):",
        "",
        "| operation | " + " | ".join(SCALAR_TITLES[s] for s in SCALARS[:-1]) + " |",
        "|---|" + "---:|" * (len(SCALARS) - 1),
    ]
    for op in ops:
        cells = [fmt_err(runs.get(f"{op}/soma/{s}", {}).get("max_err")) for s in SCALARS[:-1]]
        out.append(f"| {op} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def kdl_table(runs, ops):
    rows = []
    for name, r in sorted(runs.items(), key=lambda kv: kv[1]["order"]):
        p = split(name)
        if not p or p[1] != "KDL" or p[0] not in ops:
            continue
        soma = runs.get(f"{p[0]}/soma/double", {})
        ratio = soma["ns"] / r["ns"] if soma.get("ns") and r.get("ns") else None
        rows.append(
            f"| {p[0]} | {fmt_ns(soma.get('ns'))} | `{p[2]}` | {fmt_ns(r.get('ns'))} | "
            f"{fmt_ratio(ratio)} | {fmt_err(soma.get('max_err'))} | {fmt_err(r.get('max_err'))} | "
            f"{md_cell(r.get('label', ''))} |")
    if not rows:
        return "No KDL rows (Orocos KDL was not found when the benchmarks were configured)."
    return "\n".join([
        "soma double beside Orocos KDL (double only). The ratio is soma double time / KDL time "
        "(above 1: KDL is faster). Errors as above, each against the 256-bit mpfr value of the "
        "map that row really computes:",
        "",
        "| operation | soma double | KDL call | KDL | soma / KDL | soma error | KDL error | what the KDL row computes |",
        "|---|---:|---|---:|---:|---:|---:|---|",
    ] + rows)


def noise(runs):
    cvs = [(r["cv"], n) for n, r in runs.items() if "cv" in r]
    if not cvs:
        return ""
    cv, name = max(cvs)
    return (f"Noise: the largest coefficient of variation over the repetitions is "
            f"{100 * cv:.1f}% ({name}).")


def extras(contexts):
    notes = []
    for c in contexts:
        if "soma_gap_addDelta_vs_se3_exp" in c:
            notes.append("On these inputs KDL's `addDelta` differs from the SE(3) exponential by "
                         f"up to {c['soma_gap_addDelta_vs_se3_exp']} and `diff` from the SE(3) "
                         f"log by up to {c['soma_gap_diff_vs_se3_log']} (max-norm): they are "
                         "the maps of SO(3) × R³, not of SE(3).")
        if "soma_kdl_getrot_worst" in c:
            notes.append(f"KDL's `GetRot` is least accurate near θ = π: "
                         f"{c['soma_kdl_getrot_worst']}.")
    return "\n".join(f"- {n}" for n in notes)


def render(runs, contexts, load, time_field, flags):
    groups = []
    for name in sorted(runs, key=lambda n: runs[n]["order"]):
        p = split(name)
        if p:
            g = p[0].split(".", 1)[0]
            if g not in groups:
                groups.append(g)
    reps = max((r.get("reps") or 0) for r in runs.values())
    parts = [header(contexts, load, time_field, reps, flags), ""]
    for g in groups:
        ops = []
        for name in sorted(runs, key=lambda n: runs[n]["order"]):
            p = split(name)
            if p and p[0].split(".", 1)[0] == g and p[0] not in ops:
                ops.append(p[0])
        parts += [f"### {g}", "", ladder_table(runs, ops), "", kdl_table(runs, ops), ""]
    tail = [noise(runs), extras(contexts)]
    parts += [t for t in tail if t]
    return "\n".join(parts).rstrip() + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", nargs="+", help="Google Benchmark JSON files")
    ap.add_argument("--out", help="markdown file to update between the bench markers")
    ap.add_argument("--load", default="", help="load average text from uptime, for the header")
    ap.add_argument("--time", choices=["cpu", "real"], default="cpu",
                    help="which time to tabulate (default: cpu)")
    ap.add_argument("--flags", default="(not given)",
                    help="the flags the benchmarks were run with, for the header")
    ap.add_argument("--title", default="Benchmarks", help="title of a newly created file")
    args = ap.parse_args()
    runs, contexts = load_runs(args.results, f"{args.time}_time")
    body = f"{BEGIN}\n<!-- generated by scripts/bench_table.py: edit outside the markers -->\n" \
           f"{render(runs, contexts, args.load, f'{args.time}_time', args.flags)}{END}"
    if not args.out:
        sys.stdout.write(body + "\n")
        return
    text = ""
    if os.path.exists(args.out):
        with open(args.out, encoding="utf-8") as f:
            text = f.read()
    if BEGIN in text and END in text:
        text = re.sub(re.escape(BEGIN) + ".*?" + re.escape(END), lambda _: body, text,
                      count=1, flags=re.S)
    else:
        text = f"# {args.title}\n\n{body}\n" + (f"\n{text}" if text else "")
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main()
