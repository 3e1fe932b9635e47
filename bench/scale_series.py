#!/usr/bin/env python3
"""Replicate an OSM extract K times as disjoint networks side by side.

    bench/scale_series.py IN K OUT [--margin DEG] [--offset N] [--layout JSON]

IN      .osm, .opl, .osm.pbf, .osm.gz, .osm.bz2 (anything but .opl is first
        turned into OPL with `osmium cat IN -o X.opl`)
K       number of copies (>= 1)
OUT     .opl (written directly) or anything osmium writes, e.g. .osm.pbf
        (the OPL is piped into `osmium cat -F opl - -o OUT`)

Copy c (0..K-1) adds c*OFFSET to every node / way / relation id and to every
reference (way node refs, relation members), and is laid out on a grid of
ceil(sqrt(K)) columns: column c % cols shifts longitudes by col*DX, row
c // cols shifts latitudes by row*DY, where DX / DY are the extract's lon /
lat span plus --margin degrees (default 0.05, ~3.5-5.5 km: well beyond
railodd's road corridor and station distances, so copies do not interact).
A grid that would leave [-180, 180] / [-90, 90] grows west / south instead.

OFFSET (default) is the smallest power of ten above the largest id of any
type, so ids of copy c stay above every id of copy c-1. The output is written
type by type (all nodes of all copies, then all ways, then all relations),
copy by copy; an input sorted by type and id therefore gives a sorted output,
as PBF readers expect (checked: sorted input is required, see --check).

--layout JSON writes the layout (K, offset, dx, dy, columns, rows, the
bounding box of every copy) for the caller, e.g. to select copy 0 by --bbox.

Standard library only (plus the osmium binary for format conversion).
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

SCALE = 10_000_000  # OPL coordinates carry 7 decimals


def die(msg):
    print(f"scale_series.py: {msg}", file=sys.stderr)
    sys.exit(1)


def to_opl(path, tmpdir):
    if path.endswith(".opl"):
        return path
    out = os.path.join(tmpdir, "input.opl")
    subprocess.run(["osmium", "cat", path, "-o", out, "--overwrite"], check=True)
    return out


def split_by_type(opl, tmpdir):
    """One pass: split the OPL into node / way / relation files, track the
    coordinate extent (in 1e-7 degrees), the largest id and the sort order."""
    files = {t: os.path.join(tmpdir, f"{t}.opl") for t in "nwr"}
    outs = {t: open(files[t], "w", encoding="utf-8") for t in "nwr"}
    xmin = ymin = math.inf
    xmax = ymax = -math.inf
    max_id = 0
    last = {t: None for t in "nwr"}
    order = "nwr"
    last_type_idx = 0
    sorted_ok = True
    counts = {t: 0 for t in "nwr"}
    with open(opl, encoding="utf-8") as f:
        for line in f:
            if not line.strip():
                continue
            t = line[0]
            if t not in outs:
                die(f"unsupported OPL object type '{t}' (changesets?)")
            sp = line.find(" ")
            oid = int(line[1:sp] if sp > 0 else line[1:].rstrip("\n"))
            if oid < 0:
                die("negative ids are not supported")
            max_id = max(max_id, oid)
            ti = order.index(t)
            if ti < last_type_idx or (last[t] is not None and oid <= last[t]):
                sorted_ok = False
            last_type_idx = ti
            last[t] = oid
            counts[t] += 1
            if t == "n":
                for tok in line.rstrip("\n").split(" ")[1:]:
                    if tok.startswith("x") and len(tok) > 1:
                        v = round(float(tok[1:]) * SCALE)
                        xmin = min(xmin, v)
                        xmax = max(xmax, v)
                    elif tok.startswith("y") and len(tok) > 1:
                        v = round(float(tok[1:]) * SCALE)
                        ymin = min(ymin, v)
                        ymax = max(ymax, v)
            outs[t].write(line if line.endswith("\n") else line + "\n")
    for o in outs.values():
        o.close()
    if xmin == math.inf:
        die("no node with a location in the input")
    return files, (xmin, ymin, xmax, ymax), max_id, sorted_ok, counts


def fmt_coord(v):
    """1e-7 degree integer -> OPL decimal (as osmium writes it)."""
    sign = "-" if v < 0 else ""
    v = abs(v)
    s = f"{v // SCALE}.{v % SCALE:07d}".rstrip("0").rstrip(".")
    return sign + s


def shift_line(line, id_add, dx, dy):
    toks = line.rstrip("\n").split(" ")
    t = toks[0][0]
    toks[0] = t + str(int(toks[0][1:]) + id_add)
    for i in range(1, len(toks)):
        tok = toks[i]
        if not tok:
            continue
        k = tok[0]
        if t == "n" and k == "x" and len(tok) > 1:
            toks[i] = "x" + fmt_coord(round(float(tok[1:]) * SCALE) + dx)
        elif t == "n" and k == "y" and len(tok) > 1:
            toks[i] = "y" + fmt_coord(round(float(tok[1:]) * SCALE) + dy)
        elif t == "w" and k == "N" and len(tok) > 1:
            refs = []
            for r in tok[1:].split(","):
                # "n123" or, with locations on ways, "n123x1.2y3.4"
                j = 1
                while j < len(r) and r[j].isdigit():
                    j += 1
                if len(r) > j:
                    die("way node locations in OPL are not supported")
                refs.append("n" + str(int(r[1:j]) + id_add))
            toks[i] = "N" + ",".join(refs)
        elif t == "r" and k == "M" and len(tok) > 1:
            mems = []
            for m in tok[1:].split(","):
                at = m.index("@")
                mems.append(m[0] + str(int(m[1:at]) + id_add) + m[at:])
            toks[i] = "M" + ",".join(mems)
    return " ".join(toks) + "\n"


def layout(k, bbox, margin_deg):
    xmin, ymin, xmax, ymax = bbox
    margin = round(margin_deg * SCALE)
    dx = (xmax - xmin) + margin
    dy = (ymax - ymin) + margin
    cols = math.ceil(math.sqrt(k))
    rows = math.ceil(k / cols)
    # grow east / north when that stays in range, else west / south
    sx = 1 if xmax + (cols - 1) * dx <= 180 * SCALE else -1
    sy = 1 if ymax + (rows - 1) * dy <= 90 * SCALE else -1
    if sx < 0 and xmin - (cols - 1) * dx < -180 * SCALE:
        die(f"{cols} columns of {dx / SCALE:.4f} deg do not fit in [-180, 180]")
    if sy < 0 and ymin - (rows - 1) * dy < -90 * SCALE:
        die(f"{rows} rows of {dy / SCALE:.4f} deg do not fit in [-90, 90]")
    shifts = []
    for c in range(k):
        col, row = c % cols, c // cols
        shifts.append((sx * col * dx, sy * row * dy))
    return dx, dy, cols, rows, shifts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("input")
    ap.add_argument("k", type=int)
    ap.add_argument("output")
    ap.add_argument("--margin", type=float, default=0.05,
                    help="degrees between copies (default 0.05)")
    ap.add_argument("--offset", type=int, default=0,
                    help="id offset per copy (default: power of ten above the largest id)")
    ap.add_argument("--layout", help="write the layout as JSON here")
    a = ap.parse_args()
    if a.k < 1:
        die("K must be >= 1")
    if not os.path.exists(a.input):
        die(f"no such input: {a.input}")
    tmpdir = tempfile.mkdtemp(prefix="scale_series.")
    try:
        opl = to_opl(a.input, tmpdir)
        files, bbox, max_id, sorted_ok, counts = split_by_type(opl, tmpdir)
        if not sorted_ok and not a.output.endswith(".opl"):
            die("input is not sorted by type and id; run `osmium sort` on it first")
        offset = a.offset or 10 ** len(str(max_id))
        if offset <= max_id:
            die(f"--offset {offset} must exceed the largest id {max_id}")
        if (a.k - 1) * offset + max_id >= 2 ** 63:
            die("ids would overflow int64")
        dx, dy, cols, rows, shifts = layout(a.k, bbox, a.margin)

        if a.output.endswith(".opl"):
            sink = open(a.output, "w", encoding="utf-8")
            proc = None
        else:
            proc = subprocess.Popen(
                ["osmium", "cat", "-F", "opl", "-", "-o", a.output, "--overwrite"],
                stdin=subprocess.PIPE, text=True, encoding="utf-8")
            sink = proc.stdin
        for t in "nwr":
            for c in range(a.k):
                sx, sy = shifts[c]
                with open(files[t], encoding="utf-8") as f:
                    for line in f:
                        sink.write(shift_line(line, c * offset, sx, sy))
        sink.close()
        if proc and proc.wait() != 0:
            die("osmium cat failed")

        if a.layout:
            xmin, ymin, xmax, ymax = bbox
            copies = []
            for c, (sx, sy) in enumerate(shifts):
                copies.append({
                    "copy": c,
                    "id_offset": c * offset,
                    "bbox": [(xmin + sx) / SCALE, (ymin + sy) / SCALE,
                             (xmax + sx) / SCALE, (ymax + sy) / SCALE],
                })
            with open(a.layout, "w", encoding="utf-8") as f:
                json.dump({
                    "input": a.input, "k": a.k, "output": a.output,
                    "id_offset": offset, "max_input_id": max_id,
                    "dx_deg": dx / SCALE, "dy_deg": dy / SCALE,
                    "margin_deg": a.margin, "columns": cols, "rows": rows,
                    "input_counts": counts, "copies": copies,
                }, f, indent=1)
                f.write("\n")
    finally:
        shutil.rmtree(tmpdir, ignore_errors=True)


if __name__ == "__main__":
    main()
