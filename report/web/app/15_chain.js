// A chain (data.chains) lays profile tracks end to end on one x axis in metres. This
// maps roads, s and track chainage onto that axis and back, so the charts can draw
// road-based data (curvature, elevation) and element-based data on the same x.
(function (RA) {
  'use strict';

  // One segment per track piece: x from xa to xb, road s from sa to sb (either order).
  function buildChain(D, chain) {
    const trackInfo = new Map();
    const segs = [];
    // Along a route (meta.along_route) chainage is already the route's: each
    // track sits at its own start. Elsewhere tracks are laid end to end.
    const along = !!(D.meta && D.meta.along_route);
    let off = 0;
    for (const [t, rev] of chain.parts) {
      const tr = D.tracks[t];
      if (!tr) continue;
      const len = tr.length, start = tr.start || 0;
      const base = along ? start : off;
      trackInfo.set(t, {off: base, rev: !!rev, len, start});
      const X = (ch) => base + (rev ? len - (ch - start) : ch - start);
      for (const [road, s0, s1, ch0, ch1, prev] of tr.pieces) {
        let xa = X(ch0), xb = X(ch1);
        let sa = prev ? s1 : s0, sb = prev ? s0 : s1;
        if (xb < xa) { [xa, xb] = [xb, xa]; [sa, sb] = [sb, sa]; }
        segs.push({road, xa, xb, sa, sb, track: t});
      }
      off += len;
    }
    segs.sort((a, b) => a.xa - b.xa);
    const byRoad = new Map();
    for (const g of segs) {
      if (!byRoad.has(g.road)) byRoad.set(g.road, []);
      byRoad.get(g.road).push(g);
    }
    const C = {chain, length: chain.length, segs, trackInfo, byRoad};
    // Chain x of a track chainage (null when the track is not on this chain).
    C.x = (track, ch) => {
      const ti = trackInfo.get(track);
      if (!ti) return null;
      return ti.off + (ti.rev ? ti.len - (ch - ti.start) : ch - ti.start);
    };
    // +1 when chainage grows with x on this chain, -1 when the track runs backwards.
    C.dir = (track) => { const ti = trackInfo.get(track); return ti && ti.rev ? -1 : 1; };
    C.locate = (x) => locate(segs, x);
    C.xOfRoadS = (road, s) => xOfRoadS(byRoad, road, s);
    return C;
  }

  function segSign(g) { return (g.sb - g.sa) >= 0 ? 1 : -1; }
  function sOfX(g, x) {
    const w = g.xb - g.xa;
    return w > 0 ? g.sa + (g.sb - g.sa) * (x - g.xa) / w : g.sa;
  }
  function xOfS(g, s) {
    const w = g.sb - g.sa;
    return w !== 0 ? g.xa + (g.xb - g.xa) * (s - g.sa) / w : g.xa;
  }

  function locate(segs, x) {
    let lo = 0, hi = segs.length - 1, best = null;
    while (lo <= hi) {  // last segment starting at or before x
      const mid = (lo + hi) >> 1;
      if (segs[mid].xa <= x) { best = mid; lo = mid + 1; } else hi = mid - 1;
    }
    if (best == null) best = 0;
    const g = segs[best];
    if (!g) return null;
    const xc = Math.max(g.xa, Math.min(g.xb, x));
    return {road: g.road, s: sOfX(g, xc), track: g.track};
  }

  function xOfRoadS(byRoad, road, s) {
    const list = byRoad.get(road);
    if (!list) return null;
    for (const g of list) {
      const lo = Math.min(g.sa, g.sb) - 0.01, hi = Math.max(g.sa, g.sb) + 0.01;
      if (s >= lo && s <= hi) return {x: xOfS(g, s), sign: segSign(g)};
    }
    return null;
  }

  // Fitted curvature along the chain; sign follows the direction of growing x.
  // A null between tracks keeps uPlot from drawing a line across unrelated tracks.
  function curvatureSeries(D, C) {
    const xs = [], ys = [];
    let lastTrack = null;
    for (const g of C.segs) {
      const road = D.roads[g.road];
      if (!road) continue;
      if (lastTrack != null && g.track !== lastTrack) { xs.push(g.xa); ys.push(null); }
      lastTrack = g.track;
      const sign = segSign(g), lo = Math.min(g.sa, g.sb), hi = Math.max(g.sa, g.sb);
      const pts = [[lo, RA.curvatureAt(road, lo)]];
      const k = road.k;
      for (let j = 0; j + 1 < k.length; j += 2) if (k[j] > lo && k[j] < hi) pts.push([k[j], k[j + 1]]);
      pts.push([hi, RA.curvatureAt(road, hi)]);
      const mapped = pts.map(([s, kv]) => [xOfS(g, s), sign * kv]);
      if (mapped.length > 1 && mapped[0][0] > mapped[mapped.length - 1][0]) mapped.reverse();
      for (const [x, y] of mapped) { xs.push(x); ys.push(y); }
    }
    return [xs, ys];
  }

  function nodeCurvatureSeries(D, C) {
    const nk = D.node_curvature || [];
    const pts = [];
    for (let i = 0; i + 2 < nk.length; i += 3) {
      const m = C.xOfRoadS(nk[i], nk[i + 1]);
      if (m) pts.push([m.x, m.sign * nk[i + 2]]);
    }
    pts.sort((a, b) => a[0] - b[0]);
    return [pts.map((p) => p[0]), pts.map((p) => p[1])];
  }

  // Elevation at the road vertices along the chain.
  function elevationSeries(D, C) {
    const xs = [], ys = [];
    let lastTrack = null;
    for (const g of C.segs) {
      const road = D.roads[g.road];
      if (!road || !road.z) continue;
      if (lastTrack != null && g.track !== lastTrack) { xs.push(g.xa); ys.push(null); }
      lastTrack = g.track;
      const lo = Math.min(g.sa, g.sb), hi = Math.max(g.sa, g.sb);
      const step = road.n > 1 ? road.length / (road.n - 1) : road.length;
      const pts = [];
      for (let i = 0; i < road.n; i++) {
        const s = i * step;
        if (s >= lo - 1e-6 && s <= hi + 1e-6) pts.push([xOfS(g, s), road.z[i]]);
      }
      if (pts.length > 1 && pts[0][0] > pts[pts.length - 1][0]) pts.reverse();
      for (const [x, y] of pts) { xs.push(x); ys.push(y); }
    }
    return [xs, ys];
  }

  // Stretch elements of one kind as a step line: value(e) over [x0, x1], a gap between
  // stretches that do not touch. Elements of tracks off the chain are left out.
  function stepSeries(D, C, kindId, value) {
    const st = [];
    for (const e of D.elementsOf(kindId)) {
      const v = value(e);
      if (v == null || !isFinite(v)) continue;
      const a = C.x(e[4], e[5]), b = C.x(e[4], e[6]);
      if (a == null) continue;
      st.push([Math.min(a, b), Math.max(a, b), v]);
    }
    st.sort((p, q) => p[0] - q[0]);
    const xs = [], ys = [];
    let end = null;
    for (const [a, x1, v] of st) {
      // Overlapping stretches (both directions of a line, say) would zigzag once the
      // rows are sorted by x: each one starts where the previous one ended.
      const x0 = end == null ? a : Math.max(a, end);
      if (x0 >= x1) continue;
      if (end != null && x0 > end + 0.5) { xs.push((end + x0) / 2); ys.push(null); }
      xs.push(x0, x1); ys.push(v, v);
      end = x1;
    }
    return [xs, ys];
  }

  RA.buildChain = buildChain;
  RA.chainSeries = {curvatureSeries, nodeCurvatureSeries, elevationSeries, stepSeries};
})(window.RailoddApp = window.RailoddApp || {});
