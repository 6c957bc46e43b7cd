#!/usr/bin/env python3
"""Thesis Table 4.2 for the bundled-thesis models: runs `stratamesh-cli remesh` on each model at
each number of sites and prints input and output side by side as a Markdown table.

Counts marked * exclude the box (as `info` and thesis Table 3.1 do).

usage: scripts/remesh-table.py [--cli build/bin/stratamesh-cli] [--data ../shared/data]
                               [--models modelA1,modelA2,modelA5] [--sites 1000,5000,10000]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

COLUMNS = ["Model", "#Sites", "#V", "#T", "#Surf.*", "#Lines*", "#Corners*", "Min angle (deg)", "< 30° (%)",
           "Avg Q", "Area (m²)", "Sampling (s)", "Mesh (s)", "Hausdorff (% bbox diag.)", "Valid"]


def row(model, sites, side, report):
    counts = side["counts"]["without_box"]
    mesh = side["mesh"]
    timings = report["timings"] if sites != "Input" else {}
    hausdorff = f'{report["hausdorff_pct_bbox"]:.3f}' if sites != "Input" else ""
    return [model, str(sites), str(mesh["vertices"]), str(mesh["triangles"]), str(counts["surfaces"]),
            str(counts["lines"]), str(counts["corners"]), f'{mesh["min_angle_deg"]:.2f}',
            f'{mesh["pct_triangles_angle_below_30"]:.2f}', f'{mesh["mean_quality"]:.3f}', f'{mesh["area"]:.4g}',
            f'{timings["sampling_s"]:.2f}' if timings else "", f'{timings["mesh_s"]:.2f}' if timings else "",
            hausdorff, "yes" if side["validity"]["valid"] else "NO"]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=os.path.join(root, "build", "bin", "stratamesh-cli"))
    parser.add_argument("--data", default=os.environ.get("STRATAMESH_DATA_DIR", os.path.join(root, "..", "shared", "data")))
    parser.add_argument("--models", default="modelA1,modelA2,modelA5")
    parser.add_argument("--sites", default="1000,5000,10000")
    args = parser.parse_args()

    print("| " + " | ".join(COLUMNS) + " |")
    print("|" + "---|" * len(COLUMNS))
    with tempfile.TemporaryDirectory() as tmp:
        for model in args.models.split(","):
            path = os.path.join(args.data, model + ".ml")
            if not os.path.exists(path):
                sys.exit(f"{path}: no such model (set --data or STRATAMESH_DATA_DIR)")
            for i, sites in enumerate(args.sites.split(",")):
                out = os.path.join(tmp, f"{model}_{sites}.ml")
                report_path = os.path.join(tmp, f"{model}_{sites}.json")
                done = subprocess.run([args.cli, "remesh", path, "--sites", sites, "-o", out, "--report", report_path],
                                      capture_output=True, text=True)
                if done.returncode != 0:
                    sys.exit(f"remesh {model} at {sites} sites failed:\n{done.stderr}")
                with open(report_path) as f:
                    report = json.load(f)
                if i == 0:
                    print("| " + " | ".join(row(model, "Input", report["input"], report)) + " |")
                print("| " + " | ".join(row("", sites, report["output"], report)) + " |", flush=True)


if __name__ == "__main__":
    main()
