#!/usr/bin/env python3
"""The summaries of a sharded batch (Slurm) against an unsharded one (local).

Usage: compare_summaries.py LOCAL_OUTROOT SHARDED_OUTROOT SHARDS. Summary
names and batch_merged.json's summaries/shards name a run's own sharding by
design; everything else about the routes must agree. (merge itself refuses
shard summaries of another routes file or shard count.) Exits 1 naming the
first difference.
"""
import glob, json, sys
local, slurm, shards = sys.argv[1], sys.argv[2], int(sys.argv[3])


def load(p):
    with open(p) as f:
        return json.load(f)


lsum = load(f"{local}/batch_summary.json")
parts = [load(p) for p in sorted(glob.glob(f"{slurm}/batch_summary.shard-*-of-{shards}.json"))]
if len(parts) != shards:
    sys.exit(f"FAIL: {len(parts)} shard summaries, expected {shards}")
sroutes = {r["id"]: r for p in parts for r in p["routes"]}
lroutes = {r["id"]: r for r in lsum["routes"]}
if sroutes != lroutes:
    bad = sorted(i for i in lroutes.keys() | sroutes.keys() if lroutes.get(i) != sroutes.get(i))
    sys.exit(f"FAIL: route {bad[0]}: local {lroutes.get(bad[0])} vs Slurm {sroutes.get(bad[0])}")
if any(r["status"] != "ok" for r in lroutes.values()):
    sys.exit(f"FAIL: not every route ok: {lsum['counts']}")
lm, sm = load(f"{local}/batch_merged.json"), load(f"{slurm}/batch_merged.json")
if sm["shards"] != {"count": shards, "missing": []}:
    sys.exit(f"FAIL: merged shards {sm['shards']}")
for m in (lm, sm):
    del m["summaries"], m["shards"]
if lm != sm:
    k = next(k for k in lm.keys() | sm.keys() if lm.get(k) != sm.get(k))
    sys.exit(f"FAIL: batch_merged.json differs in '{k}'")
print(f"summaries agree on {len(lroutes)} routes; batch_merged.json equal but for summaries/shards")
