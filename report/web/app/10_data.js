// Decoding of the embedded report data (report/web/data_format.md) into typed arrays,
// plus the geometric look-ups every view needs: a place on a road at s, a stretch of a
// road between two s, and the s nearest to a clicked point.
(function (RA) {
  'use strict';

  function decodeRoad(r, index) {
    const n = r.pts.length / 2;
    const lat = new Float64Array(n), lon = new Float64Array(n);
    let x = 0, y = 0;
    for (let i = 0; i < n; i++) {
      x += r.pts[2 * i]; y += r.pts[2 * i + 1];
      lon[i] = x * 1e-6; lat[i] = y * 1e-6;
    }
    let z = null;
    if (r.z) {
      z = new Float64Array(r.z.length);
      let acc = 0;
      for (let i = 0; i < r.z.length; i++) { acc += r.z[i]; z[i] = acc / 100; }
    }
    return {index, id: r.id, rail: !!r.rail, junction: r.junction, length: r.length,
      osm: r.osm || '', n, lat, lon, z, k: r.k || []};
  }

  // The raw element rows stay as they are (170k on a big network); views read them
  // through these small accessors instead of building an object per element.
  function makeElementApi(D) {
    const kindIdx = {};
    D.kinds.forEach((k, i) => {
      kindIdx[k.id] = i;
      k.attrIndex = {};
      k.attrs.forEach((a, j) => { k.attrIndex[a] = j; });
    });
    D.kindIdx = kindIdx;
    // A row lists its kind's attributes as known when it was written: pad
    // the earlier, shorter ones so every view reads one column per attribute.
    for (const e of D.elements) {
      const n = D.kinds[e[0]].attrs.length;
      while (e[7].length < n) e[7].push(null);
    }
    D.attr = (e, name) => {
      const j = D.kinds[e[0]].attrIndex[name];
      return j == null ? undefined : e[7][j];
    };
    D.kindOf = (e) => D.kinds[e[0]];
    D.isKind = (e, id) => D.kinds[e[0]].id === id;
    let byKind = null;
    // Lists of element rows per kind id, built once on first use.
    D.elementsOf = (id) => {
      if (!byKind) {
        byKind = {};
        for (const k of D.kinds) byKind[k.id] = [];
        for (const e of D.elements) byKind[D.kinds[e[0]].id].push(e);
      }
      return byKind[id] || [];
    };
    D.kindsMatching = (re) => D.kinds.filter((k) => re.test(k.id)).map((k) => k.id);
  }

  function decode(raw) {
    const D = Object.assign({}, raw);
    D.roads = raw.roads.map(decodeRoad);
    D.elements = raw.elements || [];
    D.kinds = raw.kinds || [];
    D.osm = raw.osm || [];
    D.tracks = raw.tracks || [];
    D.chains = raw.chains || [];
    makeElementApi(D);
    D.roadById = {};
    D.roads.forEach((r) => { D.roadById[r.id] = r; });
    return D;
  }

  // Vertex i of n sits at s = length*i/(n-1), so s maps to a fractional vertex index.
  function vertexAt(road, s) {
    if (road.n < 2 || !(road.length > 0)) return 0;
    const f = Math.max(0, Math.min(1, s / road.length)) * (road.n - 1);
    return f;
  }

  function positionAt(road, s) {
    const f = vertexAt(road, s);
    const i = Math.min(road.n - 2, Math.floor(f));
    if (i < 0) return [road.lat[0], road.lon[0]];
    const t = f - i;
    return [road.lat[i] + (road.lat[i + 1] - road.lat[i]) * t,
      road.lon[i] + (road.lon[i + 1] - road.lon[i]) * t];
  }

  // The stretch of a road between s0 and s1 (either order) as Leaflet [lat, lng] pairs.
  function slice(road, s0, s1) {
    if (s1 < s0) { const t = s0; s0 = s1; s1 = t; }
    const out = [positionAt(road, s0)];
    const f0 = vertexAt(road, s0), f1 = vertexAt(road, s1);
    for (let i = Math.floor(f0) + 1; i < f1; i++) out.push([road.lat[i], road.lon[i]]);
    out.push(positionAt(road, s1));
    return out;
  }

  function latlngs(road) {
    const out = new Array(road.n);
    for (let i = 0; i < road.n; i++) out[i] = [road.lat[i], road.lon[i]];
    return out;
  }

  // Projects a clicked point onto the road polyline in a local metric frame (the
  // roads are short enough for an equirectangular approximation) and returns its s.
  function nearestS(road, lat, lng) {
    const kx = Math.cos(lat * Math.PI / 180) * 111320, ky = 110540;
    const step = road.n > 1 ? road.length / (road.n - 1) : 0;
    let best = Infinity, bestS = 0;
    for (let i = 0; i + 1 < road.n; i++) {
      const ax = (road.lon[i] - lng) * kx, ay = (road.lat[i] - lat) * ky;
      const bx = (road.lon[i + 1] - lng) * kx, by = (road.lat[i + 1] - lat) * ky;
      const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
      const t = l2 > 0 ? Math.max(0, Math.min(1, -(ax * dx + ay * dy) / l2)) : 0;
      const px = ax + dx * t, py = ay + dy * t, d = px * px + py * py;
      if (d < best) { best = d; bestS = (i + t) * step; }
    }
    return bestS;
  }

  // Curvature of a road at s from its [s0,k0,s1,k1,...] joints (linear in between).
  function curvatureAt(road, s) {
    const k = road.k;
    for (let j = 0; j + 3 < k.length; j += 2) {
      if (s >= k[j] && s <= k[j + 2]) {
        const ds = k[j + 2] - k[j];
        return ds > 0 ? k[j + 1] + (k[j + 3] - k[j + 1]) * (s - k[j]) / ds : k[j + 3];
      }
    }
    return k.length ? k[k.length - 1] : 0;
  }

  function osmOf(D, e) { return D.osm[e[8]] || ''; }

  Object.assign(RA, {decode, positionAt, slice, latlngs, nearestS, curvatureAt, osmOf});
})(window.RailoddApp = window.RailoddApp || {});
