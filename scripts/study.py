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


DASK_CONNECT_SECONDS = 5


def connect_dask(address):
    """A client of the scheduler at `address`, or one line on stderr and exit status 2 (no traceback) when Dask is
    missing or nothing answers there within DASK_CONNECT_SECONDS."""
    try:
        from distributed import Client  # Dask's own scheduler; only needed for --dask
    except ImportError as e:
        print(f"study: --dask needs Dask's distributed package ({e}); scripts/setup.sh installs it", file=sys.stderr)
        sys.exit(2)
    try:
        return Client(address, timeout=DASK_CONNECT_SECONDS)
    except Exception as e:  # distributed raises OSError, TimeoutError or ValueError, by address and version
        reason = str(e).splitlines()[0] if str(e) else type(e).__name__
        print(f"study: no Dask scheduler answered at {address} within {DASK_CONNECT_SECONDS} s ({reason})",
              file=sys.stderr)
        sys.exit(2)


def run_dask(binary, cases, roots, address):
    from distributed import as_completed

    rows, progress = {}, Progress(len(cases))
    with connect_dask(address) as client:
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


def read_defaults(binary):
    """The baseline's setting columns and values (physim_study --defaults): a row with these is at the defaults,
    whichever family it belongs to."""
    lines = subprocess.run([binary, "--defaults"], capture_output=True, text=True, check=True).stdout.split()
    return dict(zip(lines[0].split(","), lines[1].split(",")))


EXAMPLES_HZ = "40"  # the examples' rate (the framework's Simulation steps at 40 Hz)


def scene_points(rows, scene, defaults):
    """A scene's cases: family, setting, cost, error; `defaults` whether every setting is the baseline's,
    `examples` whether it is the baseline at the examples' rate; `spread` the cost's (None when not measured)."""
    points = []
    for r in rows:
        if r["scene"] != scene:
            continue
        spread = r.get("cpu_spread")
        others = all(r.get(c) == v for c, v in defaults.items() if c != "hz")
        points.append({"family": r["family"], "setting": r["setting"], "cost": float(r["cpu_s_per_sim_s"]),
                       "error": float(r["error"]), "defaults": others and r.get("hz") == defaults.get("hz"),
                       "examples": others and r.get("hz") == EXAMPLES_HZ,
                       "spread": float(spread) if spread not in (None, "", "nan") else None})
    return points


def floor_for(points):
    """Where an error of exactly 0 is drawn on a log axis: a decade below the smallest non-zero error."""
    positive = [p["error"] for p in points if p["error"] > 0]
    return min(positive) / 10 if positive else 1e-6


FAMILY_COLOURS = {"rate": 1, "substeps": 2, "iterations": 4, "relax": 8, "hertz": 6, "damping": 7,
                  "stiff": 46, "ccd": 28}  # ROOT colours


# The plot's geometry, as draw_pareto sets it: canvas pixels, the pad's margins (NDC), the labels' text size (a
# fraction of the pad's height) and a Helvetica character's mean width in ems, for placing labels apart.
CANVAS_W, CANVAS_H = 1100, 720
MARGIN_L, MARGIN_R, MARGIN_T, MARGIN_B = 0.12, 0.2, 0.12, 0.1
LABEL_SIZE = 0.024
CHAR_EMS = 0.55


MIXED_COLOUR = 922  # ROOT's kGray + 2: a label naming several families' settings


def label_groups(points, y, to_ndc):
    """The points' labels, one per group of points drawn on top of each other (within half a label's height): the
    settings joined ("discrete, exact") in their family's colour, or, where the group holds several families,
    each family named ("hertz 240; damping 0.5, 1") in grey. Points at the defaults are left unlabelled: the star
    and the note under the legend say what they are, and every family's default case piles up there."""
    groups = []
    for p in points:
        if p["defaults"]:
            continue
        x, yy = to_ndc(p["cost"], y(p))
        for g in groups:
            if abs(g["x"] - x) < 0.012 and abs(g["y"] - yy) < LABEL_SIZE / 2:
                g["parts"].setdefault(p["family"], [])
                if p["setting"] not in g["parts"][p["family"]]:
                    g["parts"][p["family"]].append(p["setting"])
                break
        else:
            groups.append({"x": x, "y": yy, "parts": {p["family"]: [p["setting"]]}})
    for g in groups:
        if len(g["parts"]) == 1:
            family, settings = next(iter(g["parts"].items()))
            g["texts"], g["colour"] = settings, FAMILY_COLOURS[family]
        else:
            g["texts"] = ["; ".join(f"{f} {', '.join(s)}" for f, s in g["parts"].items())]
            g["colour"] = MIXED_COLOUR
    return groups


def place_labels(groups, markers):
    """Places each label beside its point where it covers no marker (`markers`: (x, y, half size) in NDC) and no
    label placed before, and stays in the frame: to the right first, then stepped up and down by a label's height,
    then to the left. Returns dicts in NDC; `moved` when a label is not beside its point (draw a leader)."""
    char_w = LABEL_SIZE * CANVAS_H / CANVAS_W * CHAR_EMS
    h = LABEL_SIZE * 1.15
    placed = []
    boxes = [(x - r, y - r, x + r, y + r) for x, y, r in markers]
    for g in sorted(groups, key=lambda g: (g["x"], g["y"])):
        text = ", ".join(g["texts"])
        w = char_w * len(text)
        gap = 0.01
        candidates = []
        for k in (0, 1, -1, 2, -2, 3, -3, 4, -4):
            candidates.append((g["x"] + gap, g["y"] + k * h - 0.35 * h, k != 0))
        for k in (0, 1, -1, 2, -2):
            candidates.append((g["x"] - gap - w, g["y"] + k * h - 0.35 * h, k != 0))
        chosen = candidates[0]
        for x, yy, moved in candidates:
            box = (x, yy, x + w, yy + h)
            inside = MARGIN_L <= x and x + w <= 1 - MARGIN_R + 0.005 and MARGIN_B <= yy and yy + h <= 1 - MARGIN_T
            if inside and not any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3] for b in boxes):
                chosen = (x, yy, moved)
                break
        x, yy, moved = chosen
        boxes.append((x, yy, x + w, yy + h))
        placed.append({"x": x, "y": yy, "w": w, "text": text, "colour": g["colour"], "moved": moved,
                       "px": g["x"], "py": g["y"]})
    return placed


def draw_pareto(scene, meaning, points, path, defaults_text):
    import ROOT

    ROOT.gROOT.SetBatch(True)
    ROOT.gStyle.SetOptStat(0)
    ROOT.gErrorIgnoreLevel = ROOT.kWarning  # no "file created" line per plot
    floor = floor_for(points)
    y = lambda p: max(p["error"], floor)
    canvas = ROOT.TCanvas(f"c_{scene}", scene, CANVAS_W, CANVAS_H)
    canvas.SetLogx()
    canvas.SetLogy()
    canvas.SetGrid()
    canvas.SetLeftMargin(MARGIN_L)
    canvas.SetRightMargin(MARGIN_R)
    canvas.SetTopMargin(MARGIN_T)
    canvas.SetBottomMargin(MARGIN_B)
    zero_note = " (0 drawn at %.1g)" % floor if any(p["error"] == 0 for p in points) else ""
    multi = ROOT.TMultiGraph("mg", f";CPU seconds per simulated second (log);error{zero_note} (log)")
    legend = ROOT.TLegend(0.81, 0.35, 0.995, 0.88)
    legend.SetTextSize(0.028)
    keep = [multi, legend]
    for family in [f for f in FAMILY_COLOURS if any(p["family"] == f for p in points)]:
        fam = [p for p in points if p["family"] == family]
        g = ROOT.TGraph(len(fam))
        for i, p in enumerate(fam):
            g.SetPoint(i, p["cost"], y(p))
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
    for p, style, size, colour, text in ((baseline(points), 29, 3.5, ROOT.kGreen + 2, "defaults"),
                                         (examples_point(points), 33, 3.0, ROOT.kAzure + 1, "examples (40 Hz)")):
        if p:
            mark = ROOT.TGraph(1)
            mark.SetPoint(0, p["cost"], y(p))
            mark.SetMarkerStyle(style)
            mark.SetMarkerSize(size)
            mark.SetMarkerColor(colour)
            multi.Add(mark, "P")
            legend.AddEntry(mark, text, "p")
            keep.append(mark)
    multi.Draw("A")
    xs = [p["cost"] for p in points]
    ys = [y(p) for p in points]
    x0, x1 = min(xs) / 1.5, max(xs) * 2.5  # room for the labels right of the points
    y0, y1 = min(ys) / 2, max(ys) * 2
    multi.GetXaxis().SetLimits(x0, x1)
    multi.SetMinimum(y0)
    multi.SetMaximum(y1)
    multi.GetXaxis().SetTitleOffset(1.2)
    multi.GetXaxis().SetMoreLogLabels()
    multi.GetYaxis().SetMoreLogLabels()
    multi.GetYaxis().SetTitleOffset(1.6)

    def to_ndc(cx, cy):
        fx = (math.log10(cx) - math.log10(x0)) / (math.log10(x1) - math.log10(x0))
        fy = (math.log10(cy) - math.log10(y0)) / (math.log10(y1) - math.log10(y0))
        return MARGIN_L + fx * (1 - MARGIN_L - MARGIN_R), MARGIN_B + fy * (1 - MARGIN_B - MARGIN_T)

    text = ROOT.TLatex()
    text.SetNDC()
    text.SetTextSize(LABEL_SIZE)
    leader = ROOT.TLine()
    leader.SetNDC()
    leader.SetLineStyle(3)
    markers = [to_ndc(p["cost"], y(p)) + (0.006,) for p in points]
    markers += [to_ndc(p["cost"], y(p)) + (0.016,) for p in (baseline(points), examples_point(points)) if p]
    for a in place_labels(label_groups(points, y, to_ndc), markers):
        text.SetTextColor(a["colour"])
        text.DrawLatex(a["x"], a["y"], a["text"])
        if a["moved"]:  # a dotted leader from the point to the label it was moved apart to
            leader.SetLineColor(a["colour"])
            end = a["x"] if a["x"] > a["px"] else a["x"] + a["w"]
            leader.DrawLineNDC(a["px"], a["py"], end, a["y"] + 0.4 * LABEL_SIZE)
    legend.Draw()
    head = ROOT.TLatex()
    head.SetNDC()
    head.SetTextSize(0.04)
    head.DrawLatex(0.1, 0.95, f"{scene}: error against cost, one curve per setting family")
    head.SetTextSize(0.028)
    head.DrawLatex(0.1, 0.905, f"error: {meaning}; labels: the setting")
    note = ROOT.TLatex()  # under the legend: what "defaults" are
    note.SetNDC()
    note.SetTextSize(0.024)
    note.DrawLatex(0.815, 0.31, "defaults:")
    note.DrawLatex(0.815, 0.275, defaults_text)
    canvas.SaveAs(path)


def baseline(points):
    """The defaults' case (60 Hz, WorldSettings' defaults, discrete): the rate family's where it has one, else any
    family's case at the defaults (the quick sweep's stack has only substeps; its 8 is the defaults)."""
    at = [p for p in points if p["defaults"]]
    return next((p for p in at if p["family"] == "rate"), at[0] if at else None)


def examples_point(points):
    """The examples' rate (40 Hz) with everything else at the defaults, if the sweep has it."""
    return next((p for p in points if p["examples"]), None)


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


MIN_FIT_POINTS = 3
MIN_SLOPE = 0.5  # below it a tenth of the error would cost over 100x: the family has met a floor, not a law
MIN_R2 = 0.9     # the errors past the defaults lie on a line in log-log, or no law is claimed


def tenfold_by_slope(points, family):
    """Fit error ~ cost^-k over a family's points from the defaults' setting on (what buying accuracy beyond the
    defaults costs): a tenfold gain then costs 10^(1/k) times more. Returns (k, None), or (None, why not): a fit
    over the settings below the defaults (the quick sweep's stack, 1 to 8 substeps) answers another question, and a
    line through fewer than three points is no law."""
    fam = [p for p in points if p["family"] == family]
    start = next((i for i, p in enumerate(fam) if p["defaults"]), None)
    if len(fam) < 2:  # a single case (the quick sweep's other scenes): no family swept, nothing to say
        return None, None
    if start is None:
        return None, f"no cost law fitted: the sweep has no {family} setting at the defaults"
    fam = [p for p in fam[start:] if p["error"] > 0]
    if len(fam) < MIN_FIT_POINTS:
        return None, (f"no cost law fitted: {len(fam)} of its settings from the defaults on "
                      f"{'has' if len(fam) == 1 else 'have'} a non-zero error, {MIN_FIT_POINTS} needed")
    if fam[-1]["error"] >= fam[0]["error"]:
        return None, "no cost law: past the defaults more of it does not cut the error"
    xs = [math.log10(p["cost"]) for p in fam]
    ys = [math.log10(p["error"]) for p in fam]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return None, None
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    syy = sum((y - my) ** 2 for y in ys)
    k = -sxy / sxx
    r2 = sxy * sxy / (sxx * syy) if syy > 0 else 0.0
    if k < MIN_SLOPE:
        return None, f"no cost law: past the defaults its error falls too slowly for one (slope {k:.2f}, a floor)"
    if r2 < MIN_R2:
        return None, f"no cost law: past the defaults its errors do not lie on a line (r^2 {r2:.2f})"
    return k, None


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


def defaults_words(defaults):
    """The baseline in words, from physim_study --defaults."""
    return f"{defaults.get('hz', '60')} Hz, {defaults.get('substeps', '8')} substeps"


def write_summary(out, rows, meanings, cases, elapsed, how, defaults):
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    order = {}
    for s, f, v in cases:
        order.setdefault(f, [])
        if v not in order[f]:
            order[f].append(v)
    lines = ["# Accuracy study: summary", "",
             f"{len(rows)} cases" + (f", {elapsed:.0f} s wall" if elapsed is not None else "") + f" ({how}). Cost: CPU seconds of the process per simulated "
             "second of stepping (the fastest of repeated runs of the case, repeated until the fastest three agree "
             "within 10 % or 3 s of CPU time: their spread is in the table; wall seconds beside it); error: each "
             "scene's measure against its trusted answer. Figures compare within this run only. The defaults "
             f"({defaults_words(defaults)}, WorldSettings' defaults, discrete detection) are marked wherever a family "
             "has them; the examples step at 40 Hz.",
             ""]
    for scene in scenes:
        pts = scene_points(rows, scene, defaults)
        front = pareto(pts)
        lines += [f"## {scene}", "", f"Error: {meanings.get(scene, '')}.", ""]
        if os.path.exists(os.path.join(out, f"pareto_{scene}.png")):
            lines += [f"![{scene}](pareto_{scene}.png)", ""]
        lines += ["| family | setting | CPU s per sim s | spread | wall s per sim s | error | Pareto | at |",
                  "|---|---|---|---|---|---|---|---|"]
        for p, r in zip(pts, [r for r in rows if r["scene"] == scene]):
            mark = "yes" if p in front else ""
            at = "defaults" if p["defaults"] else "examples (40 Hz)" if p["examples"] else ""
            spread = f"{100 * p['spread']:.0f} %" if p["spread"] is not None else ""
            lines.append(f"| {p['family']} | {p['setting']} | {p['cost']:.3g} | {spread} "
                         f"| {float(r['wall_s_per_sim_s']):.3g} | {p['error']:.3g} | {mark} | {at} |")
        lines.append("")
        base, ten = baseline(pts), tenfold(pts)
        if base:
            lines.append(f"- defaults ({defaults_words(defaults)}): cost {base['cost']:.3g}, error {base['error']:.3g}")
            same = [p for p in pts if p["defaults"]]
            if len(same) > 1:  # one setting, several cases: how far apart their costs came
                low, high = min(p["cost"] for p in same), max(p["cost"] for p in same)
                lines.append(f"- the defaults ran as {len(same)} cases ({', '.join(p['family'] for p in same)}): "
                             f"CPU cost {low:.3g} to {high:.3g}, {high / low:.2f}x apart")
        ex = examples_point(pts)
        if ex:
            lines.append(f"- the examples' 40 Hz: cost {ex['cost']:.3g}, error {ex['error']:.3g}")
        if ten:
            p, ratio = ten
            lines.append(f"- a tenth of the defaults' error: {p['family']} {p['setting']}, {ratio:.2g}x the cost")
        elif base and base["error"] > 0:
            lines.append("- a tenth of the defaults' error: no setting in the sweep reaches it")
        for family in ("rate", "substeps", "stiff"):  # error against cost is a power law while these pay
            k, why = tenfold_by_slope(pts, family)
            if k:
                lines.append(f"- {family}: error ~ cost^-{k:.2f} from the defaults on, so a tenth of the error costs "
                             f"about {10 ** (1 / k):.2g}x")
            elif why:
                lines.append(f"- {family}: {why}")
        for family in order:
            effect = family_effect(pts, family, order[family])
            if effect:
                lines.append(f"- {effect}")
        lines.append("")
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(lines))


def report(out, rows, meanings, cases, no_plots, elapsed, how, defaults):
    if not no_plots:
        for scene in dict.fromkeys(r["scene"] for r in rows):
            pts = scene_points(rows, scene, defaults)
            if len(pts) > 1:
                draw_pareto(scene, meanings.get(scene, ""), pts, os.path.join(out, f"pareto_{scene}.png"),
                            defaults_words(defaults))
    write_summary(out, rows, meanings, cases, elapsed, how, defaults)


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
    defaults = read_defaults(binary)
    if args.replot:
        with open(os.path.join(out, "runs.csv")) as f:
            ordered = list(csv.DictReader(f))
        cases = [(r["scene"], r["family"], r["setting"]) for r in ordered]
        report(out, ordered, meanings, cases, args.no_plots, None, "redrawn from runs.csv", defaults)
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

    report(out, ordered, meanings, cases, args.no_plots, elapsed, how, defaults)
    print(f"[study] {len(ordered)} cases in {elapsed:.0f} s: {out}/runs.csv, runs.root, summary.md, "
          f"pareto_<scene>.png", file=sys.stderr)


if __name__ == "__main__":
    main()
