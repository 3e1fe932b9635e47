#!/usr/bin/env python3
"""Helper of bench/compare.sh (a benchmark, not a test).

  compare_geometry.py analyse FILE.xodr
      plan-view figures of one OpenDRIVE file as JSON: roads, rail roads,
      geometry records by kind (all roads and rail roads), and the curvature
      jumps at the joints between consecutive records of each rail road.

  compare_geometry.py report WORKDIR OUT.json
      reads what compare.sh left in WORKDIR (runs.tsv, meta.tsv, the outputs,
      the `railodd validate --json` files, the timed report.json), prints the
      side-by-side table and writes the same figures to OUT.json.

A rail road is one whose lanes other than the centre lane are all of type
`rail` or `tram` (the definition `railodd validate` uses; SUMO netconvert
writes lane type `rail` for edges that only allow rail classes).

End curvatures of the records: line 0; arc @curvature; spiral @curvStart /
@curvEnd; paramPoly3 (x'y'' - y'x'') / (x'^2 + y'^2)^1.5 at p = 0 and at
p = 1 (pRange normalized) or p = @length (pRange arcLength); poly3
v'' / (1 + v'^2)^1.5 at u = 0 and at the u where its arc length reaches
@length (Newton on a Gauss-Legendre arc-length integral).
"""
import json
import math
import os
import statistics
import sys
import xml.etree.ElementTree as ET

KINDS = ("line", "arc", "spiral", "poly3", "paramPoly3")
RAIL_LANES = {"rail", "tram"}
CURV_LIMIT = 1e-6  # railodd validate's limit for rail curvature jumps, 1/m

# 10-point Gauss-Legendre on [-1, 1]
_GL_X = (-0.9739065285171717, -0.8650633666889845, -0.6794095682990244,
         -0.4333953941292472, -0.1488743389816312, 0.1488743389816312,
         0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
         0.9739065285171717)
_GL_W = (0.0666713443086881, 0.1494513491505806, 0.2190863625159820,
         0.2692667143361577, 0.2955242247147529, 0.2955242247147529,
         0.2692667143361577, 0.2190863625159820, 0.1494513491505806,
         0.0666713443086881)


def _f(el, name, default=0.0):
    v = el.get(name)
    return float(v) if v is not None else default


def _poly3_u_end(b, c, d, length):
    """u at which the arc length of v(u) = a + b u + c u^2 + d u^3 is length."""
    def dv(u):
        return b + 2 * c * u + 3 * d * u * u

    def arc(u):
        h = u / 2.0
        return sum(w * math.sqrt(1 + dv(h * x + h) ** 2) for x, w in zip(_GL_X, _GL_W)) * h

    u = length / math.sqrt(1 + b * b)
    for _ in range(30):
        step = (arc(u) - length) / math.sqrt(1 + dv(u) ** 2)
        u -= step
        if abs(step) < 1e-12 * max(1.0, length):
            break
    return u


def end_curvatures(geom):
    """(kind, curvature at start, curvature at end, heading at start, heading
    at end) of a <geometry> element."""
    length = _f(geom, "length")
    hdg = _f(geom, "hdg")
    for child in geom:
        kind = child.tag
        if kind == "line":
            return kind, 0.0, 0.0, hdg, hdg
        if kind == "arc":
            k = _f(child, "curvature")
            return kind, k, k, hdg, hdg + k * length
        if kind == "spiral":
            k0, k1 = _f(child, "curvStart"), _f(child, "curvEnd")
            return kind, k0, k1, hdg, hdg + 0.5 * (k0 + k1) * length
        if kind == "paramPoly3":
            bu, cu, du = _f(child, "bU"), _f(child, "cU"), _f(child, "dU")
            bv, cv, dv = _f(child, "bV"), _f(child, "cV"), _f(child, "dV")
            p_end = length if child.get("pRange", "arcLength") == "arcLength" else 1.0

            def kappa(p):
                x1, y1 = bu + 2 * cu * p + 3 * du * p * p, bv + 2 * cv * p + 3 * dv * p * p
                x2, y2 = 2 * cu + 6 * du * p, 2 * cv + 6 * dv * p
                n = (x1 * x1 + y1 * y1) ** 1.5
                return (x1 * y2 - y1 * x2) / n if n > 0 else 0.0

            def tangent(p):
                return math.atan2(bv + 2 * cv * p + 3 * dv * p * p, bu + 2 * cu * p + 3 * du * p * p)
            return kind, kappa(0.0), kappa(p_end), hdg + tangent(0.0), hdg + tangent(p_end)
        if kind == "poly3":
            b, c, d = _f(child, "b"), _f(child, "c"), _f(child, "d")
            u1 = _poly3_u_end(b, c, d, length)

            def kappa(u):
                d1, d2 = b + 2 * c * u + 3 * d * u * u, 2 * c + 6 * d * u
                return d2 / (1 + d1 * d1) ** 1.5
            return (kind, kappa(0.0), kappa(u1), hdg + math.atan(b),
                    hdg + math.atan(b + 2 * c * u1 + 3 * d * u1 * u1))
    return None, 0.0, 0.0, hdg, hdg


def _percentile(sorted_values, q):
    if not sorted_values:
        return None
    k = (len(sorted_values) - 1) * q
    lo, hi = math.floor(k), math.ceil(k)
    return sorted_values[lo] + (sorted_values[hi] - sorted_values[lo]) * (k - lo)


def analyse(path):
    roads = rail_roads = 0
    rail_length = 0.0
    kinds_all = {k: 0 for k in KINDS}
    kinds_rail = {k: 0 for k in KINDS}
    jumps = []
    kinks = []
    worst = (0.0, "")
    worst_kink = (0.0, "")
    for _, el in ET.iterparse(path, events=("end",)):
        if el.tag != "road":
            continue
        roads += 1
        lane_types = [lane.get("type") for side in ("left", "right")
                      for sec in el.iterfind("lanes/laneSection")
                      for lane in sec.iterfind(side + "/lane")]
        is_rail = bool(lane_types) and all(t in RAIL_LANES for t in lane_types)
        prev_end = None
        prev_hdg = None
        for geom in el.iterfind("planView/geometry"):
            kind, k0, k1, h0, h1 = end_curvatures(geom)
            if kind in kinds_all:
                kinds_all[kind] += 1
                if is_rail:
                    kinds_rail[kind] += 1
            if is_rail:
                if prev_end is not None:
                    j = abs(k0 - prev_end)
                    jumps.append(j)
                    if j > worst[0]:
                        worst = (j, "road %s s=%.3f" % (el.get("id"), _f(geom, "s")))
                    h = abs(math.remainder(h0 - prev_hdg, 2 * math.pi))
                    kinks.append(h)
                    if h > worst_kink[0]:
                        worst_kink = (h, "road %s s=%.3f" % (el.get("id"), _f(geom, "s")))
                prev_end = k1
                prev_hdg = h1
        if is_rail:
            rail_roads += 1
            rail_length += _f(el, "length")
        el.clear()
    jumps.sort()
    kinks.sort()
    return {
        "file": path,
        "bytes": os.path.getsize(path),
        "roads": roads,
        "rail_roads": rail_roads,
        "rail_length_km": round(rail_length / 1000.0, 3),
        "records_by_kind": kinds_all,
        "rail_records_by_kind": kinds_rail,
        "rail_records_per_km": round(sum(kinds_rail.values()) / (rail_length / 1000.0), 2) if rail_length > 0 else None,
        "rail_joints": len(jumps),
        "rail_curvature_jump_max_per_m": jumps[-1] if jumps else None,
        "rail_curvature_jump_max_where": worst[1],
        "rail_curvature_jump_p95_per_m": _percentile(jumps, 0.95),
        "rail_curvature_jump_p50_per_m": _percentile(jumps, 0.50),
        "rail_joints_over_1e-6": sum(1 for j in jumps if j > CURV_LIMIT),
        "rail_joints_over_1e-3": sum(1 for j in jumps if j > 1e-3),
        "rail_heading_jump_max_rad": kinks[-1] if kinks else None,
        "rail_heading_jump_max_where": worst_kink[1],
        "rail_heading_jump_p95_rad": _percentile(kinks, 0.95),
        "rail_joints_heading_over_1e-4": sum(1 for h in kinks if h > 1e-4),
    }


# ---------------------------------------------------------------- report

TOOLS = (("railodd", "railodd convert"),
         ("netconvert_repair", "netconvert + topology.repair"),
         ("netconvert", "netconvert (all types)"),
         ("netconvert_rail_repair", "netconvert rail + repair"),
         ("netconvert_rail", "netconvert (rail only)"),
         ("osmium", "osmium cat -f opl (floor)"))


def _read_tsv(path):
    rows = []
    with open(path) as fh:
        header = fh.readline().rstrip("\n").split("\t")
        for line in fh:
            if line.strip():
                rows.append(dict(zip(header, line.rstrip("\n").split("\t"))))
    return rows


def _validate_summary(path):
    if not os.path.exists(path) or os.path.getsize(path) == 0:
        return None
    with open(path) as fh:
        try:
            d = json.load(fh)
        except json.JSONDecodeError:
            return None
    s = d.get("summary", {})
    checks = {}
    for f in d.get("findings", []):
        key = f.get("severity", "?") + ":" + f.get("check", "?")
        checks[key] = checks.get(key, 0) + 1
    out = {"passed": d.get("passed"), "errors": d.get("errors"), "warnings": d.get("warnings"),
           "roads": s.get("roads"), "rail_roads": s.get("rail_roads"),
           "findings_by_check": dict(sorted(checks.items(), key=lambda kv: -kv[1]))}
    for key in ("max_gap_m", "max_heading_jump_rad", "max_rail_curvature_jump_per_m"):
        if key in s:
            out[key] = s[key].get("value")
            out[key + "_where"] = s[key].get("where")
    return out


def _fmt(v, digits=3):
    if v is None:
        return "-"
    if isinstance(v, float):
        if v == 0:
            return "0"
        if abs(v) < 1e-3 or abs(v) >= 1e6:
            return "%.2e" % v
        return ("%." + str(digits) + "g") % v
    return str(v)


def report(work, out_json):
    meta = {r["key"]: r["value"] for r in _read_tsv(os.path.join(work, "meta.tsv"))}
    runs = _read_tsv(os.path.join(work, "runs.tsv"))
    tools = {}
    for tool, label in TOOLS:
        rs = [r for r in runs if r["tool"] == tool]
        if not rs:
            continue
        ok = [r for r in rs if r["exit"] == "0"]
        entry = {"label": label, "command": meta.get("cmd_" + tool, ""), "runs": len(rs),
                 "failed_runs": len(rs) - len(ok),
                 "wall_s": [float(r["wall_s"]) for r in rs],
                 "cpu_s": [float(r["cpu_s"]) for r in rs],
                 "peak_rss_mb": [round(int(r["maxrss_kb"]) / 1024.0, 1) for r in rs],
                 "load1_before": [float(r["load1"]) for r in rs],
                 "exit_codes": [int(r["exit"]) for r in rs]}
        if ok:
            entry["median_wall_s"] = statistics.median(float(r["wall_s"]) for r in ok)
            entry["median_cpu_s"] = round(statistics.median(float(r["cpu_s"]) for r in ok), 2)
            entry["median_peak_rss_mb"] = round(statistics.median(int(r["maxrss_kb"]) for r in ok) / 1024.0, 1)
        out_size = meta.get("size_" + tool)
        if out_size:
            entry["output_bytes"] = int(out_size)
        if meta.get("size_" + tool + "_outdir"):
            entry["outdir_bytes"] = int(meta["size_" + tool + "_outdir"])
        tools[tool] = entry

    def ratio(a, b, key):
        if a in tools and b in tools and key in tools[a] and key in tools[b] and tools[b][key] > 0:
            return round(tools[a][key] / tools[b][key], 3)
        return None

    ratios = {}
    for other in ("netconvert", "netconvert_rail", "osmium"):
        ratios["railodd/" + other] = {"time": ratio("railodd", other, "median_wall_s"),
                                      "cpu": ratio("railodd", other, "median_cpu_s"),
                                      "memory": ratio("railodd", other, "median_peak_rss_mb")}

    geometry = {}
    for tool, fname in (("railodd", "railodd.xodr"), ("netconvert", "netconvert.xodr"),
                        ("netconvert_rail", "netconvert_rail.xodr")):
        p = os.path.join(work, fname)
        if os.path.exists(p):
            g = analyse(p)
            g["file"] = fname
            g["validate"] = _validate_summary(os.path.join(work, tool + ".validate.json"))
            geometry[tool] = g

    split = None
    rp = os.path.join(work, "railodd_timed", "report.json")
    if os.path.exists(rp):
        with open(rp) as fh:
            rep = json.load(fh)
        t = rep.get("timings_s") or {}
        total = sum(t.values())
        split = {"source": meta.get("split_source", ""),
                 "phases_s": {k: round(v, 3) for k, v in t.items()},
                 "sum_s": round(total, 3),
                 "fit_tracks_share": round(t.get("fit_tracks", 0.0) / total, 3) if total > 0 else None,
                 "track_km": rep.get("geometry", {}).get("summary", {}).get("length_km"),
                 "track_ways": rep.get("input", {}).get("track_ways"),
                 "road_ways": rep.get("input", {}).get("road_ways")}

    result = {
        "name": meta.get("name"), "input": meta.get("input"), "osm_xml": meta.get("osm_xml"),
        "osm_xml_bytes": int(meta.get("osm_xml_bytes", 0)),
        "date": meta.get("date"), "machine": meta.get("machine"), "nproc": int(meta.get("nproc", 0)),
        "load_start": meta.get("load_start"), "load_end": meta.get("load_end"),
        "runs_per_tool": int(meta.get("runs", 0)),
        "runs_railodd": int(meta.get("runs_railodd", meta.get("runs", 0))), "railodd": meta.get("railodd"),
        "railodd_version": meta.get("railodd_version"), "netconvert_version": meta.get("netconvert_version"),
        "osmium_version": meta.get("osmium_version"),
        "notes": {k[5:]: v for k, v in meta.items() if k.startswith("note_")},
        "tools": tools, "ratios": ratios, "geometry": geometry, "railodd_phases": split,
        "goal": {"time_vs_netconvert": 0.1, "memory_vs_netconvert": 0.5, "time_vs_osmium": 3.0},
    }
    goal = {}
    r = ratios["railodd/netconvert"]
    if r["time"] is not None:
        goal["time_vs_netconvert_met"] = r["time"] <= 0.1
    if r["memory"] is not None:
        goal["memory_vs_netconvert_met"] = r["memory"] <= 0.5
    if r["cpu"] is not None:
        goal["cpu_vs_netconvert_met"] = r["cpu"] <= 0.1
    if ratios["railodd/osmium"]["time"] is not None:
        goal["time_vs_osmium_met"] = ratios["railodd/osmium"]["time"] <= 3.0
    if ratios["railodd/osmium"]["cpu"] is not None:
        goal["cpu_vs_osmium_met"] = ratios["railodd/osmium"]["cpu"] <= 3.0
    result["goal_met"] = goal

    os.makedirs(os.path.dirname(os.path.abspath(out_json)), exist_ok=True)
    with open(out_json, "w") as fh:
        json.dump(result, fh, indent=1)
        fh.write("\n")
    print_table(result)
    print("\nwrote " + out_json)


def print_table(res):
    print("\n== %s (%s, %s MB OSM XML), %d run(s) each (railodd %d), %s, %d cores, load %s -> %s" % (
        res["name"], res["input"], _fmt(res["osm_xml_bytes"] / 1e6), res["runs_per_tool"], res["runs_railodd"],
        res["date"], res["nproc"], res["load_start"], res["load_end"]))
    print("%-28s %10s %10s %10s %12s %s" % ("tool", "median s", "cpu s", "peak MB", "output MB", "runs (wall s)"))
    for tool, _ in TOOLS:
        t = res["tools"].get(tool)
        if not t:
            continue
        fail = "" if not t["failed_runs"] else "  FAILED %d/%d" % (t["failed_runs"], t["runs"])
        print("%-28s %10s %10s %10s %12s %s%s" % (
            t["label"], _fmt(t.get("median_wall_s")), _fmt(t.get("median_cpu_s")), _fmt(t.get("median_peak_rss_mb")),
            _fmt(t["output_bytes"] / 1e6) if "output_bytes" in t else "-",
            " ".join("%.2f" % w for w in t["wall_s"]), fail))
    print("ratios railodd/X (wall, cpu, memory): " + "; ".join(
        "%s %s, %s, %s" % (k.split("/")[1], _fmt(v["time"]), _fmt(v["cpu"]), _fmt(v["memory"]))
        for k, v in res["ratios"].items()))
    for k, v in res["notes"].items():
        print("note %s: %s" % (k, v))
    g = res["geometry"]
    if g:
        cols = [k for k in ("railodd", "netconvert", "netconvert_rail") if k in g]
        print("\n%-34s" % "geometry" + "".join("%18s" % c for c in cols))
        rows = [("roads", lambda x: x["roads"]), ("rail roads", lambda x: x["rail_roads"]),
                ("rail km", lambda x: x["rail_length_km"])]
        for k in KINDS:
            rows.append(("rail records: " + k, lambda x, k=k: x["rail_records_by_kind"][k]))
        rows += [("rail records per km", lambda x: x["rail_records_per_km"]),
                 ("rail joints", lambda x: x["rail_joints"]),
                 ("curv. jump max 1/m", lambda x: x["rail_curvature_jump_max_per_m"]),
                 ("curv. jump p95 1/m", lambda x: x["rail_curvature_jump_p95_per_m"]),
                 ("joints > 1e-6 1/m", lambda x: x["rail_joints_over_1e-6"]),
                 ("heading jump max rad", lambda x: x["rail_heading_jump_max_rad"]),
                 ("heading jump p95 rad", lambda x: x["rail_heading_jump_p95_rad"]),
                 ("joints > 1e-4 rad", lambda x: x["rail_joints_heading_over_1e-4"]),
                 ("validate verdict", lambda x: None if not x["validate"] else ("pass" if x["validate"]["passed"] else "FAIL")),
                 ("validate errors/warnings", lambda x: None if not x["validate"] else "%s/%s" % (x["validate"]["errors"], x["validate"]["warnings"])),
                 ("validate max gap m", lambda x: None if not x["validate"] else x["validate"].get("max_gap_m")),
                 ("validate max heading jump rad", lambda x: None if not x["validate"] else x["validate"].get("max_heading_jump_rad")),
                 ("validate max rail curv jump", lambda x: None if not x["validate"] else x["validate"].get("max_rail_curvature_jump_per_m"))]
        for name, fn in rows:
            print("%-34s" % name + "".join("%18s" % _fmt(fn(g[c])) for c in cols))
    s = res.get("railodd_phases")
    if s:
        print("\nrailodd phases (%s), %s track km:" % (s["source"], _fmt(s["track_km"])))
        for k, v in sorted(s["phases_s"].items(), key=lambda kv: -kv[1]):
            print("  %-20s %9.3f s" % (k, v))
        print("  %-20s %9.3f s (fit_tracks %s)" % ("sum", s["sum_s"], _fmt(s["fit_tracks_share"])))


def main(argv):
    if len(argv) == 3 and argv[1] == "analyse":
        json.dump(analyse(argv[2]), sys.stdout, indent=1)
        print()
        return 0
    if len(argv) == 4 and argv[1] == "report":
        report(argv[2], argv[3])
        return 0
    sys.stderr.write(__doc__)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
