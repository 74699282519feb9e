#!/usr/bin/env python3
"""Review many lexicon signs at once: one PNG per group of signs, one row per sign.

Each row shows the sign at its start, middle and end (the times `gestura sign` reports), each moment
front and side, cropped to the upper body, with the gloss written on the row. Needs ffmpeg.

    tools/sign-grid.py [--lexicon data/lexicon/ase.jsonl] [--per-image 8] [--out DIR]
                       [--gestura build/bin/gestura] [--jobs 2] [GLOSS ... | --lines A-B]

Without glosses or --lines every sign of the lexicon is drawn. Prints the images it wrote.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"
W, H = 640, 360  # render size: front on the left half, side on the right half
FPS = 5
# Upper-body crops of each half (x, y, w, h) at 640x360.
FRONT = (40, 10, 240, 280)
SIDE = (380, 10, 240, 280)
SCALE = 0.62


def render_row(gestura, entry, workdir):
    """Renders one sign to a row PNG; returns (gloss, path or None, message)."""
    gloss = entry["gloss"]
    safe = re.sub(r"[^A-Za-z0-9_-]", "_", gloss)
    video = os.path.join(workdir, safe + ".mp4")
    run = subprocess.run([gestura, "sign", "--hamnosys", entry["hamnosys"], "-o", video, "--fps", str(FPS),
                          "--camera", "front,side", "--size", f"{W}x{H}"], capture_output=True, text=True)
    if run.returncode != 0:
        return gloss, None, run.stderr.strip()
    m = re.search(r"sign ([0-9.]+)\u2013([0-9.]+) s", run.stdout)
    a, b = (float(m.group(1)), float(m.group(2))) if m else (1.0, 2.0)
    n = re.search(r"([0-9]+) frames", run.stdout)
    last = int(n.group(1)) - 1 if n else round(b * FPS)
    frames = [min(last, round(t * FPS)) for t in (a, (a + b) / 2, b)]
    for i in (1, 2):  # three distinct frames, or the tile would stay blank
        frames[i] = max(frames[i], frames[i - 1] + 1)
    frames = [f - max(0, frames[2] - last) for f in frames]
    select = "+".join(f"eq(n\\,{f})" for f in frames)
    cw, ch = int(FRONT[2] * SCALE), int(FRONT[3] * SCALE)
    row = os.path.join(workdir, safe + ".png")
    label = gloss.replace("'", "\u2019").replace(":", "\\:")
    graph = (f"[0:v]select='{select}',split[a][b];"
             f"[a]crop={FRONT[2]}:{FRONT[3]}:{FRONT[0]}:{FRONT[1]},scale={cw}:{ch}[f];"
             f"[b]crop={SIDE[2]}:{SIDE[3]}:{SIDE[0]}:{SIDE[1]},scale={cw}:{ch}[s];"
             f"[f][s]hstack,tile=3x1:padding=6:color=white,"
             f"drawtext=fontfile={FONT}:text='{label}':x=6:y=4:fontsize=18:fontcolor=yellow:box=1:boxcolor=black@0.6")
    run = subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", video, "-filter_complex", graph, "-frames:v", "1",
                          "-vsync", "0", row], capture_output=True, text=True)
    os.remove(video)
    if run.returncode != 0:
        return gloss, None, run.stderr.strip()
    return gloss, row, f"{a:.2f}-{b:.2f} s"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("glosses", nargs="*")
    ap.add_argument("--lexicon", default=os.path.join(ROOT, "data", "lexicon", "ase.jsonl"))
    ap.add_argument("--lines", help="1-based line range A-B of the lexicon file")
    ap.add_argument("--per-image", type=int, default=8)
    ap.add_argument("--out", default="sign-grid")
    ap.add_argument("--gestura", default=os.path.join(ROOT, "build", "bin", "gestura"))
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    with open(args.lexicon, encoding="utf-8") as f:
        entries = [json.loads(line) for line in f if line.strip()]
    if args.lines:
        a, b = (int(x) for x in args.lines.split("-"))
        entries = entries[a - 1:b]
    if args.glosses:
        by_gloss = {e["gloss"]: e for e in entries}
        missing = [g for g in args.glosses if g not in by_gloss]
        if missing:
            sys.exit("not in the lexicon: " + " ".join(missing))
        entries = [by_gloss[g] for g in args.glosses]

    os.makedirs(args.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="sign-grid-")
    try:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            rows = list(pool.map(lambda e: render_row(args.gestura, e, work), entries))
        for gloss, path, msg in rows:
            if path is None:
                print(f"{gloss}: {msg}", file=sys.stderr)
        good = [(g, p) for g, p, _ in rows if p]
        for k in range(0, len(good), args.per_image):
            group = good[k:k + args.per_image]
            out = os.path.join(args.out, f"grid-{k // args.per_image + 1:03d}.png")
            inputs = sum((["-i", p] for _, p in group), [])
            stack = "".join(f"[{i}:v]" for i in range(len(group)))
            graph = f"{stack}vstack=inputs={len(group)}" if len(group) > 1 else "[0:v]null"
            subprocess.run(["ffmpeg", "-v", "error", "-y", *inputs, "-filter_complex", graph, out], check=True)
            print(out + ": " + " ".join(g for g, _ in group))
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
