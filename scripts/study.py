"""The accuracy study's sweep (scripts/study.sh runs it with the project's Python, where ROOT and Dask live).

Every case is one independent run of physim_study (one scene, one setting family, one setting). The cases run
in parallel on this machine (--jobs) or on an existing Dask cluster (--dask ADDRESS); each writes its own
one-row .root file, merged with ROOT's hadd into DIR/runs.root. DIR/runs.csv holds the rows in the order
`physim_study --list` gives, DIR/summary.md the tables and advice figures, DIR/pareto_<scene>.png the plots.
"""

import argparse
import concurrent.futures
import csv
import glob
import io
import math
import os
import subprocess
import sys
import time


def run_case(binary, case, root_path):
    """Runs one case; returns its CSV row (a dict). Module level so a Dask worker can run it."""
    scene, family, setting = case
    cmd = [binary, "--scene", scene, "--family", family, "--setting", setting, "--header", "--root", root_path]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited {done.returncode}: {done.stderr.strip()}")
    return next(csv.DictReader(io.StringIO(done.stdout)))


def list_cases(binary, quick):
    out = subprocess.run([binary, "--list"] + (["--quick"] if quick else []), capture_output=True, text=True,
                         check=True).stdout
    return [tuple(line.split(",")) for line in out.split()]


class Progress:
    """One stderr line per finished case: done / total, elapsed, and time left at the pace so far."""

    def __init__(self, total):
        self.total, self.done, self.start = total, 0, time.monotonic()

    def step(self, case):
        self.done += 1
        elapsed = time.monotonic() - self.start
        left = elapsed / self.done * (self.total - self.done)
        print(f"[study] {self.done}/{self.total} cases, {elapsed:.0f} s elapsed, about {left:.0f} s left "
              f"({','.join(case)})", file=sys.stderr, flush=True)


def run_local(binary, cases, roots, jobs):
    rows, progress = {}, Progress(len(cases))
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(run_case, binary, c, r): c for c, r in zip(cases, roots)}
        for f in concurrent.futures.as_completed(futures):
            rows[futures[f]] = f.result()
            progress.step(futures[f])
    return rows


def run_dask(binary, cases, roots, address):
    from distributed import Client, as_completed  # Dask's own scheduler; only needed for --dask

    rows, progress = {}, Progress(len(cases))
    with Client(address) as client:
        futures = {client.submit(run_case, binary, c, r, pure=False): c for c, r in zip(cases, roots)}
        for f in as_completed(list(futures)):
            rows[futures[f]] = f.result()
            progress.step(futures[f])
    return rows


def pareto(points):
    """The points no other point beats on both cost and error (cost ascending)."""
    front, best = [], math.inf
    for p in sorted(points, key=lambda p: (p["cost"], p["error"])):
        if p["error"] < best:
            front.append(p)
            best = p["error"]
    return front


def scene_points(rows, scene):
    return [{"family": r["family"], "setting": r["setting"], "cost": float(r["cpu_s_per_sim_s"]),
             "error": float(r["error"])} for r in rows if r["scene"] == scene]


def floor_for(points):
    """Where an error of exactly 0 is drawn on a log axis: a decade below the smallest non-zero error."""
    positive = [p["error"] for p in points if p["error"] > 0]
    return min(positive) / 10 if positive else 1e-6


FAMILY_COLOURS = {"rate": 1, "substeps": 2, "iterations": 4, "relax": 8, "hertz": 6, "damping": 7,
                  "stiff": 46, "ccd": 28}  # ROOT colours


def draw_pareto(scene, meaning, points, path):
    import ROOT

    ROOT.gROOT.SetBatch(True)
    ROOT.gStyle.SetOptStat(0)
    ROOT.gErrorIgnoreLevel = ROOT.kWarning  # no "file created" line per plot
    floor = floor_for(points)
    y = lambda p: max(p["error"], floor)
    canvas = ROOT.TCanvas(f"c_{scene}", scene, 1100, 720)
    canvas.SetLogx()
    canvas.SetLogy()
    canvas.SetGrid()
    canvas.SetLeftMargin(0.12)
    canvas.SetRightMargin(0.2)
    canvas.SetTopMargin(0.12)
    zero_note = " (0 drawn at %.1g)" % floor if any(p["error"] == 0 for p in points) else ""
    multi = ROOT.TMultiGraph("mg", f";CPU seconds per simulated second (log);error{zero_note} (log)")
    legend = ROOT.TLegend(0.81, 0.35, 0.995, 0.88)
    legend.SetTextSize(0.032)
    keep = [multi, legend]
    labels = []
    for family in [f for f in FAMILY_COLOURS if any(p["family"] == f for p in points)]:
        fam = [p for p in points if p["family"] == family]
        g = ROOT.TGraph(len(fam))
        for i, p in enumerate(fam):
            g.SetPoint(i, p["cost"], y(p))
            labels.append((p["cost"], y(p), p["setting"], FAMILY_COLOURS[family]))
        g.SetLineColor(FAMILY_COLOURS[family])
        g.SetMarkerColor(FAMILY_COLOURS[family])
        g.SetMarkerStyle(20)
        g.SetLineWidth(2)
        multi.Add(g, "LP")
        legend.AddEntry(g, family, "lp")
        keep.append(g)
    front = pareto(points)
    fg = ROOT.TGraph(len(front))
    for i, p in enumerate(front):
        fg.SetPoint(i, p["cost"], y(p))
    fg.SetLineColor(ROOT.kOrange + 1)
    fg.SetLineStyle(2)
    fg.SetLineWidth(5)
    fg.SetMarkerStyle(24)
    fg.SetMarkerSize(2.4)
    fg.SetMarkerColor(ROOT.kOrange + 1)
    multi.Add(fg, "LP")
    legend.AddEntry(fg, "Pareto front", "lp")
    keep.append(fg)
    base = baseline(points)
    if base:
        bg = ROOT.TGraph(1)
        bg.SetPoint(0, base["cost"], y(base))
        bg.SetMarkerStyle(29)
        bg.SetMarkerSize(3.5)
        bg.SetMarkerColor(ROOT.kGreen + 2)
        multi.Add(bg, "P")
        legend.AddEntry(bg, "defaults (60 Hz)", "p")
        keep.append(bg)
    multi.Draw("A")
    xs = [p["cost"] for p in points]
    ys = [y(p) for p in points]
    multi.GetXaxis().SetLimits(min(xs) / 1.5, max(xs) * 2.5)  # room for the labels right of the points
    multi.SetMinimum(min(ys) / 2)
    multi.SetMaximum(max(ys) * 2)
    multi.GetXaxis().SetTitleOffset(1.2)
    multi.GetXaxis().SetMoreLogLabels()
    multi.GetYaxis().SetMoreLogLabels()
    multi.GetYaxis().SetTitleOffset(1.6)
    text = ROOT.TLatex()
    text.SetTextSize(0.024)
    for x, yy, label, colour in labels:
        text.SetTextColor(colour)
        text.DrawLatex(x * 1.06, yy * 1.06, label)
    legend.Draw()
    head = ROOT.TLatex()
    head.SetNDC()
    head.SetTextSize(0.04)
    head.DrawLatex(0.1, 0.95, f"{scene}: error against cost, one curve per setting family")
    head.SetTextSize(0.028)
    head.DrawLatex(0.1, 0.905, f"error: {meaning}; labels: the setting")
    canvas.SaveAs(path)


def baseline(points):
    """The defaults' case: 60 Hz with everything else at WorldSettings' defaults (the rate family's 60)."""
    for p in points:
        if p["family"] == "rate" and p["setting"] == "60":
            return p
    return None


def tenfold(points):
    """From the baseline, the cheapest setting with a tenth of its error or less: (point, cost ratio)."""
    base = baseline(points)
    if base is None or base["error"] == 0:
        return None
    better = [p for p in points if p["error"] <= base["error"] / 10]
    if not better:
        return None
    p = min(better, key=lambda p: p["cost"])
    return p, p["cost"] / base["cost"]


def tenfold_by_slope(points, family):
    """Fit error ~ cost^-k over a family's points: a tenfold accuracy gain then costs 10^(1/k) times more."""
    fam = [p for p in points if p["family"] == family and p["error"] > 0]
    if len(fam) < 3 or fam[-1]["error"] >= fam[0]["error"]:
        return None
    xs = [math.log10(p["cost"]) for p in fam]
    ys = [math.log10(p["error"]) for p in fam]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return None
    k = -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return k if k > 0.2 else None


def family_effect(points, family, order):
    """What a family does on a scene, in words: no effect, or the setting past which it stops paying (no later
    setting cuts the error by 10 % more), or that it pays to the end of the sweep."""
    fam = sorted([p for p in points if p["family"] == family], key=lambda p: order.index(p["setting"]))
    if len(fam) < 2:
        return None
    errors = [p["error"] for p in fam]
    if max(errors) < 1e-12:  # every scene's error is relative or in metres: this is rounding, not a trend
        return f"{family}: no effect (every error below 1e-12: rounding)"
    if max(errors) <= 1.1 * min(errors):
        return f"{family}: no effect (error within 10 % over {fam[0]['setting']} to {fam[-1]['setting']})"
    for i, p in enumerate(fam[:-1]):
        # An error at rounding (a bullet count of 0, say) has nothing left to cut.
        if p["error"] < 1e-12 or min(errors[i + 1:]) > 0.9 * p["error"]:
            best = min(fam, key=lambda q: q["error"])
            return (f"{family}: stops paying past {p['setting']} (error {p['error']:.3g}; best in the family "
                    f"{best['error']:.3g} at {best['setting']})")
    return f"{family}: still paying at {fam[-1]['setting']} (error {fam[-1]['error']:.3g})"


def write_summary(out, rows, meanings, cases, elapsed, how):
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    order = {}
    for s, f, v in cases:
        order.setdefault(f, [])
        if v not in order[f]:
            order[f].append(v)
    lines = ["# Accuracy study: summary", "",
             f"{len(rows)} cases" + (f", {elapsed:.0f} s wall" if elapsed is not None else "") + f" ({how}). Cost: CPU seconds of the process per simulated "
             "second of stepping (the fastest of repeated runs of the case; wall seconds beside it); error: each "
             "scene's measure against its trusted answer. Figures compare within this run only.",
             ""]
    for scene in scenes:
        pts = scene_points(rows, scene)
        front = pareto(pts)
        lines += [f"## {scene}", "", f"Error: {meanings.get(scene, '')}.", ""]
        if os.path.exists(os.path.join(out, f"pareto_{scene}.png")):
            lines += [f"![{scene}](pareto_{scene}.png)", ""]
        lines += ["| family | setting | CPU s per sim s | wall s per sim s | error | Pareto |",
                  "|---|---|---|---|---|---|"]
        for p, r in zip(pts, [r for r in rows if r["scene"] == scene]):
            mark = "yes" if p in front else ""
            lines.append(f"| {p['family']} | {p['setting']} | {p['cost']:.3g} | {float(r['wall_s_per_sim_s']):.3g} "
                         f"| {p['error']:.3g} | {mark} |")
        lines.append("")
        base, ten = baseline(pts), tenfold(pts)
        if base:
            lines.append(f"- defaults (60 Hz): cost {base['cost']:.3g}, error {base['error']:.3g}")
        if ten:
            p, ratio = ten
            lines.append(f"- a tenth of the defaults' error: {p['family']} {p['setting']}, {ratio:.2g}x the cost")
        elif base and base["error"] > 0:
            lines.append("- a tenth of the defaults' error: no setting in the sweep reaches it")
        for family in ("rate", "substeps", "stiff"):  # error against cost is a power law while these pay
            k = tenfold_by_slope(pts, family)
            if k:
                lines.append(f"- {family}: error ~ cost^-{k:.2f} over the sweep, so a tenth of the error costs about "
                             f"{10 ** (1 / k):.2g}x")
        for family in order:
            effect = family_effect(pts, family, order[family])
            if effect:
                lines.append(f"- {effect}")
        lines.append("")
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(lines))


def report(out, rows, meanings, cases, no_plots, elapsed, how):
    if not no_plots:
        for scene in dict.fromkeys(r["scene"] for r in rows):
            pts = scene_points(rows, scene)
            if len(pts) > 1:
                draw_pareto(scene, meanings.get(scene, ""), pts, os.path.join(out, f"pareto_{scene}.png"))
    write_summary(out, rows, meanings, cases, elapsed, how)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", required=True, help="the physim_study program")
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("--quick", action="store_true", help="the small sweep ctest runs")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="parallel local cases (default: cores)")
    ap.add_argument("--dask", metavar="ADDRESS", help="run the cases on this Dask scheduler instead")
    ap.add_argument("--no-plots", action="store_true", help="skip the PNGs (tables and CSV only)")
    ap.add_argument("--replot", action="store_true",
                    help="run nothing: redraw summary.md and the plots from DIR/runs.csv")
    args = ap.parse_args()
    if args.jobs < 1:
        ap.error(f"--jobs must be >= 1, got {args.jobs}")
    binary = os.path.abspath(args.bin)
    out = os.path.abspath(args.out)
    meanings = dict(line.split("\t", 1) for line in
                    subprocess.run([binary, "--scenes"], capture_output=True, text=True, check=True)
                    .stdout.splitlines())
    if args.replot:
        with open(os.path.join(out, "runs.csv")) as f:
            ordered = list(csv.DictReader(f))
        cases = [(r["scene"], r["family"], r["setting"]) for r in ordered]
        report(out, ordered, meanings, cases, args.no_plots, None, "redrawn from runs.csv")
        return
    cases_dir = os.path.join(out, "cases")
    os.makedirs(cases_dir, exist_ok=True)
    for old in glob.glob(os.path.join(cases_dir, "*.root")):
        os.remove(old)  # a rerun into the same folder must not merge an earlier sweep's cases
    cases = list_cases(binary, args.quick)
    roots = [os.path.join(cases_dir, "_".join(c) + ".root") for c in cases]
    start = time.monotonic()
    if args.dask:
        rows = run_dask(binary, cases, roots, args.dask)
        how = f"Dask scheduler {args.dask}"
    else:
        rows = run_local(binary, cases, roots, args.jobs)
        how = f"{args.jobs} local jobs"
    elapsed = time.monotonic() - start
    ordered = [rows[c] for c in cases]
    with open(os.path.join(out, "runs.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(ordered[0].keys()))
        w.writeheader()
        w.writerows(ordered)

    hadd = os.path.join(os.path.dirname(sys.executable), "..", "lib", f"python{sys.version_info.major}."
                        f"{sys.version_info.minor}", "site-packages", "ROOT", "bin", "hadd")
    subprocess.run([os.path.normpath(hadd), "-f", "-v", "0", os.path.join(out, "runs.root")] + roots, check=True)

    report(out, ordered, meanings, cases, args.no_plots, elapsed, how)
    print(f"[study] {len(ordered)} cases in {elapsed:.0f} s: {out}/runs.csv, runs.root, summary.md, "
          f"pareto_<scene>.png", file=sys.stderr)


if __name__ == "__main__":
    main()
