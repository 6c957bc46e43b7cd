#!/usr/bin/env python3
"""The remesh test matrix of issue 13, judged by independent tools: `stratamesh-cli remesh` on each
model at each number of sites, then Debian's `tetgen -d` (intersections, duplicated facets) and
`tetgen -pq1.414AY` (one seed per region, 10 s limit) on the PLC of the remesh; prints one
Markdown row per run (thesis Table 4.2 columns, counts without the box, topology edits, refinement).

Models are real files (a path, or a name in the data folder: modelA1) or generated fault networks
(networkN: `stratamesh-cli synthetic network --faults N`, dips 20-40°, throws around the edge
length).

usage: scripts/remesh-matrix.py [--cli build/bin/stratamesh-cli] [--data ../shared/data]
           [--models modelA1,modelA2,modelA5,network3,network5,network8]
           [--sites 1000,2000,5000,10000] [--jobs 2] [--keep DIR] [-- EXTRA REMESH OPTIONS]
"""
import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import tempfile
import time

COLUMNS = ["model", "sites", "final sites", "#V", "#T", "S/L/C in → out", "edits", "min ∠", "% < 30°",
           "Q", "H %", "valid", "tetgen -d", "tetgen -pq1.414AY", "remesh s"]


def network_model(cli, name, folder):
    faults = int(name[len("network"):])
    path = os.path.join(folder, f"{name}.ml")
    if not os.path.exists(path):
        dip = 20 + 10 * (faults % 3)
        subprocess.run([cli, "synthetic", "network", "--faults", str(faults), "--dip", str(dip), "--horizons",
                        "3", "--throw", "20", "--edge-length", "60", "-o", path], check=True,
                       capture_output=True)
    return path


def tetgen(args, timeout):
    start = time.monotonic()
    try:
        done = subprocess.run(["tetgen"] + args, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timed out", timeout, ""
    return done.returncode, time.monotonic() - start, done.stdout + done.stderr


def judge(cli, model_path, out, folder, tag):
    """tetgen -d and tetgen -pq1.414AY on the PLC our tetmesh writes (regions seeded): more
    regions than seeds are pockets."""
    poly = os.path.join(folder, f"{tag}.poly")
    subprocess.run([cli, "tetmesh", out, "--poly", poly, "-o", os.path.join(folder, f"{tag}.vtu"),
                    "--time-limit", "10"], capture_output=True, text=True)
    if not os.path.exists(poly):
        return "no PLC", "no PLC"
    code, _, text = tetgen(["-d", "-Q", poly], 60)
    problems = re.findall(r"(intersect|duplicat)", text, re.IGNORECASE)
    d = "clean" if code == 0 and not problems else f"{len(problems)} found"
    code, seconds, text = tetgen(["-pq1.414AYQ", poly], 10)
    if code == "timed out":
        q = "timed out"
    elif code != 0:
        q = "aborted"
    else:
        ele = poly[:-5] + ".1.ele"
        tets, regions = 0, set()
        if os.path.exists(ele):
            with open(ele) as f:
                tets = int(f.readline().split()[0])
                for line in f:
                    w = line.split()
                    if len(w) >= 6 and not w[0].startswith("#"):
                        regions.add(w[5])
        seeds = 0
        with open(poly) as f:
            for line in f:
                m = re.match(r"# StrataMesh PLC: .* (\d+) regions", line)
                if m:
                    seeds = int(m.group(1))
                    break
        # -A gives a region without a seed (a pocket) an attribute of its own.
        q = (f"ok {seconds:.2f} s, {tets} tets, {len(regions)} regions for {seeds} seeds")
    return d, q


def run(cli, name, path, sites, extra, folder):
    tag = f"{name}-{sites}"
    out = os.path.join(folder, f"{tag}.ml")
    report_path = os.path.join(folder, f"{tag}.json")
    start = time.monotonic()
    done = subprocess.run([cli, "remesh", path, "--sites", str(sites), "-o", out, "--report", report_path,
                           "--allow-invalid", "--overwrite"] + extra, capture_output=True, text=True)
    seconds = time.monotonic() - start
    if done.returncode != 0 or not os.path.exists(report_path):
        return [name, str(sites), "failed: " + done.stderr.strip().splitlines()[-1] if done.stderr else "failed"]
    with open(report_path) as f:
        r = json.load(f)
    cin, cout = r["input"]["counts"]["without_box"], r["output"]["counts"]["without_box"]
    mesh = r["output"]["mesh"]
    edits = sum(v for v in r["topology_edits"].values() if isinstance(v, int)) \
        if "total" not in r["topology_edits"] else r["topology_edits"]["total"]
    d, q = judge(cli, path, out, folder, tag)
    ref = r["refinement"]
    final = f'{ref["final_sites"]}' + (f' ({ref["sized_sites"]} sized)' if "sized_sites" in ref else "")
    return [name, str(sites), final, str(mesh["vertices"]), str(mesh["triangles"]),
            f'{cin["surfaces"]}/{cin["lines"]}/{cin["corners"]} → {cout["surfaces"]}/{cout["lines"]}/{cout["corners"]}',
            str(edits), f'{mesh["min_angle_deg"]:.2f}', f'{mesh["pct_triangles_angle_below_30"]:.2f}',
            f'{mesh["mean_quality"]:.3f}', f'{r["hausdorff_pct_bbox"]:.3f}',
            "yes" if r["output"]["validity"]["valid"] else "NO", d, q, f"{seconds:.1f}"]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=os.path.join(root, "build", "bin", "stratamesh-cli"))
    parser.add_argument("--data", default=os.environ.get("STRATAMESH_DATA_DIR",
                                                         os.path.join(root, "..", "shared", "data")))
    parser.add_argument("--models", default="modelA1,modelA2,modelA5,network3,network5,network8")
    parser.add_argument("--sites", default="1000,2000,5000,10000")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--keep", help="folder for the remeshes, PLCs and reports (default: temporary)")
    args = parser.parse_args(argv)

    folder = args.keep or tempfile.mkdtemp(prefix="remesh-matrix-")
    os.makedirs(folder, exist_ok=True)
    tasks = []
    for name in args.models.split(","):
        if name.startswith("network"):
            path = network_model(args.cli, name, folder)
        elif os.path.exists(name):
            path, name = name, os.path.splitext(os.path.basename(name))[0]
        else:
            path = os.path.join(args.data, name + ".ml")
        for sites in args.sites.split(","):
            tasks.append((name, path, int(sites)))
    print("| " + " | ".join(COLUMNS) + " |")
    print("|" + "---|" * len(COLUMNS), flush=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows = pool.map(lambda t: run(args.cli, t[0], t[1], t[2], extra, folder), tasks)
        for row in rows:
            print("| " + " | ".join(row) + " |", flush=True)
    if not args.keep:
        print(f"(files in {folder})", file=sys.stderr)


if __name__ == "__main__":
    main()
