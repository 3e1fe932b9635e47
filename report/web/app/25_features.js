// ODD point elements as circle markers (no image icons: the report must not request
// any resource) and structures/platforms as highlighted stretches of their road.
(function (RA) {
  'use strict';

  const POINTS = [
    {key: 'levelCrossings', label: 'Level crossings', kinds: ['sc.xing.level'], colour: '#e63946', r: 7},
    {key: 'footCrossings', label: 'Footpath crossings', kinds: ['sc.xing.foot'], colour: '#f77f00', r: 6},
    {key: 'stations', label: 'Stations and halts', kinds: ['sc.stn.station', 'sc.stn.halt'], colour: '#2a9d8f', r: 8},
    {key: 'switches', label: 'Switches', kinds: ['sc.lay.switch'], colour: '#6a4c93', r: 4},
    {key: 'diamonds', label: 'Diamond crossings', kinds: ['sc.lay.diamond'], colour: '#9d4edd', r: 4},
    {key: 'signals', label: 'Signals', kinds: ['sc.eqp.signal'], colour: '#f5b700', r: 4},
    {key: 'bufferStops', label: 'Buffer stops', kinds: ['sc.lay.buffer'], colour: '#111111', r: 5},
    {key: 'milestones', label: 'Milestones', kinds: ['sc.eqp.milestone'], colour: '#8d99ae', r: 3, off: true},
  ];
  const STRETCHES = [
    {key: 'tunnels', label: 'Tunnels', kinds: ['sc.str.tunnel'], colour: '#343a40', weight: 10},
    {key: 'bridges', label: 'Bridges', kinds: ['sc.str.bridge'], colour: '#e76f51', weight: 10},
    {key: 'platforms', label: 'Platforms', kinds: ['sc.stn.platform'], colour: '#52b788', weight: 8},
  ];

  function pointLayer(D, def) {
    const group = L.featureGroup();
    for (const id of def.kinds) {
      for (const e of D.elementsOf(id)) {
        const road = D.roads[e[1]];
        if (!road) continue;
        const m = L.circleMarker(RA.positionAt(road, e[2]), {renderer: RA.renderer, radius: def.r,
          color: '#ffffff', weight: 1.5, fillColor: def.colour, fillOpacity: 0.95});
        m.railoddElement = e;
        m.bindPopup(() => RA.elementPopup(e), {maxWidth: 420});
        group.addLayer(m);
      }
    }
    return group;
  }

  function stretchLayer(D, def) {
    const group = L.featureGroup();
    for (const id of def.kinds) {
      for (const e of D.elementsOf(id)) {
        const road = D.roads[e[1]];
        if (!road) continue;
        const pl = L.polyline(RA.slice(road, e[2], e[3]), {renderer: RA.renderer,
          color: def.colour, weight: def.weight, opacity: 0.45, lineCap: 'butt'});
        pl.railoddElement = e;
        pl.bindPopup(() => RA.elementPopup(e), {maxWidth: 420});
        group.addLayer(pl);
      }
    }
    return group;
  }

  // Builds every point/stretch layer, including empty ones, so tests and the layer
  // panel can rely on the keys; only non-empty ones are listed in the panel.
  function drawFeatures(D, layers, overlays) {
    for (const def of STRETCHES) {
      const g = stretchLayer(D, def);
      layers[def.key] = g;
      if (g.getLayers().length) {
        overlays.push({key: def.key, label: def.label, colour: def.colour, layer: g, on: true,
          count: g.getLayers().length});
      }
    }
    for (const def of POINTS) {
      const g = pointLayer(D, def);
      layers[def.key] = g;
      if (g.getLayers().length) {
        // Thousands of signals or switches hide the tracks at network scale.
        const crowded = g.getLayers().length > 1500 && def.r <= 4;
        overlays.push({key: def.key, label: def.label, colour: def.colour, layer: g, on: !def.off && !crowded,
          count: g.getLayers().length, point: true});
      }
    }
  }

  // Where the route leaves the declared ODD: red stretches (or rings for points).
  function violationLayer(D) {
    const group = L.featureGroup();
    for (const v of (D.spec && D.spec.violations) || []) {
      const road = D.roads[v.road];
      if (!road) continue;
      const style = {renderer: RA.renderer, color: '#d00000', weight: 3, fillOpacity: 0};
      const f = v.point || Math.abs(v.s1 - v.s0) < 1 ?
        L.circleMarker(RA.positionAt(road, v.s0), Object.assign(style, {radius: 10})) :
        L.polyline(RA.slice(road, v.s0, v.s1), Object.assign(style, {weight: 7, opacity: 0.6, dashArray: '8 6'}));
      f.bindPopup(() => RA.violationPopup(v), {maxWidth: 420});
      group.addLayer(f);
    }
    return group;
  }

  // Canvas draws in insertion order: after the tracks are redrawn, points go back on top.
  function raisePoints(layers) {
    for (const def of POINTS) {
      const g = layers[def.key];
      if (g && RA.map.hasLayer(g)) g.bringToFront();
    }
    for (const key of ['violations', 'scenarios']) {
      if (layers[key] && RA.map.hasLayer(layers[key])) layers[key].bringToFront();
    }
  }

  Object.assign(RA, {drawFeatures, raisePoints, violationLayer, POINT_DEFS: POINTS, STRETCH_DEFS: STRETCHES});
})(window.RailoddApp = window.RailoddApp || {});
