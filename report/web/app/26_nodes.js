// The mapped OSM track nodes (fit.node_pts), coloured by their residual to the fitted
// line. A big network has ~60k nodes: one Leaflet layer each would be slow, so they
// are painted on one canvas of their own, redrawn when the view changes.
(function (RA) {
  'use strict';

  function decodeNodes(fit) {
    const p = fit.node_pts || [], n = p.length / 2;
    const lat = new Float64Array(n), lon = new Float64Array(n);
    let x = 0, y = 0;
    for (let i = 0; i < n; i++) {
      x += p[2 * i]; y += p[2 * i + 1];
      lon[i] = x * 1e-6; lat[i] = y * 1e-6;
    }
    const res = new Float64Array(n);
    const r = fit.node_res || [];
    for (let i = 0; i < n; i++) res[i] = (r[i] || 0) / 100;
    return {n, lat, lon, res};
  }

  // Residuals above this are drawn in the hottest colour.
  function scaleOf(fit) {
    const p95 = fit.residual_p95_m, mx = fit.residual_max_m;
    return p95 > 0 ? Math.min(mx || p95 * 2, p95 * 2) : (mx > 0 ? mx : 1);
  }

  const NodeLayer = L.Layer.extend({
    initialize: function (nodes, scale) { this._nodes = nodes; this._scale = scale; },
    onAdd: function (map) {
      this._canvas = L.DomUtil.create('canvas', 'node-canvas leaflet-zoom-hide');
      map.getPanes().overlayPane.appendChild(this._canvas);
      map.on('moveend zoomend resize', this._redraw, this);
      map.on('click', this._click, this);
      this._redraw();
    },
    onRemove: function (map) {
      L.DomUtil.remove(this._canvas);
      map.off('moveend zoomend resize', this._redraw, this);
      map.off('click', this._click, this);
    },
    _redraw: function () {
      const map = this._map, size = map.getSize(), dpr = window.devicePixelRatio || 1;
      const c = this._canvas;
      c.width = size.x * dpr; c.height = size.y * dpr;
      c.style.width = size.x + 'px'; c.style.height = size.y + 'px';
      L.DomUtil.setPosition(c, map.containerPointToLayerPoint([0, 0]));
      const ctx = c.getContext('2d');
      ctx.scale(dpr, dpr);
      const nd = this._nodes, b = map.getBounds().pad(0.05);
      const rad = map.getZoom() >= 15 ? 3.5 : 2.2;
      for (let i = 0; i < nd.n; i++) {
        if (!b.contains([nd.lat[i], nd.lon[i]])) continue;
        const p = map.latLngToContainerPoint([nd.lat[i], nd.lon[i]]);
        ctx.fillStyle = RA.ramp(nd.res[i] / this._scale);
        ctx.beginPath(); ctx.arc(p.x, p.y, rad, 0, 2 * Math.PI); ctx.fill();
      }
    },
    _click: function (ev) {
      const map = this._map, nd = this._nodes, cp = ev.containerPoint;
      let best = 49, bi = -1;  // within 7 px
      for (let i = 0; i < nd.n; i++) {
        const p = map.latLngToContainerPoint([nd.lat[i], nd.lon[i]]);
        const d = (p.x - cp.x) * (p.x - cp.x) + (p.y - cp.y) * (p.y - cp.y);
        if (d < best) { best = d; bi = i; }
      }
      if (bi < 0) return;
      L.popup().setLatLng([nd.lat[bi], nd.lon[bi]]).setContent('<div class="pop"><b>Mapped node</b>' +
        '<br>residual to the fitted line ' + RA.num(nd.res[bi], 2) + ' m</div>').openOn(map);
    },
  });

  function nodeLayer(D) {
    if (!D.fit || !D.fit.available || !D.fit.node_pts || !D.fit.node_pts.length) return null;
    const layer = new NodeLayer(decodeNodes(D.fit), scaleOf(D.fit));
    layer.railoddScale = scaleOf(D.fit);
    layer.railoddCount = D.fit.node_pts.length / 2;
    return layer;
  }

  RA.nodeLayer = nodeLayer;
})(window.RailoddApp = window.RailoddApp || {});
