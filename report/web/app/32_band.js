// The element band: one row per kind of place (tunnels, bridges, stations, crossings,
// signals, switches) drawn by a uPlot draw hook on the charts' shared x axis.
(function (RA) {
  'use strict';

  const ROWS = [
    {label: 'tunnels', kinds: ['sc.str.tunnel'], colour: '#343a40'},
    {label: 'bridges', kinds: ['sc.str.bridge'], colour: '#e76f51'},
    {label: 'platforms', kinds: ['sc.stn.platform'], colour: '#52b788'},
    {label: 'stations', kinds: ['sc.stn.station', 'sc.stn.halt'], colour: '#2a9d8f'},
    {label: 'level crossings', kinds: ['sc.xing.level', 'sc.xing.foot'], colour: '#e63946'},
    {label: 'signals', kinds: ['sc.eqp.signal'], colour: '#f5b700'},
    {label: 'switches', kinds: ['sc.lay.switch', 'sc.lay.diamond', 'sc.lay.buffer'], colour: '#6a4c93'},
  ];

  // Chain x ranges of every element of each row kind on the chain's tracks.
  function rowItems(D, C) {
    return ROWS.map((row) => {
      const items = [];
      for (const id of row.kinds) {
        for (const e of D.elementsOf(id)) {
          const a = C.x(e[4], e[5]);
          if (a == null) continue;
          const b = C.x(e[4], e[6]);
          items.push({x0: Math.min(a, b), x1: Math.max(a, b), e, point: D.kindOf(e).point});
        }
      }
      items.sort((p, q) => p.x0 - q.x0);
      return Object.assign({items}, row);
    });
  }

  function drawRows(u, rows) {
    const ctx = u.ctx, bb = u.bbox, dpr = window.devicePixelRatio || 1;
    const h = bb.height / rows.length;
    const {min, max} = u.scales.x;
    ctx.save();
    ctx.beginPath(); ctx.rect(bb.left, bb.top, bb.width, bb.height); ctx.clip();
    rows.forEach((row, r) => {
      const yc = bb.top + h * (r + 0.5);
      ctx.fillStyle = row.colour; ctx.strokeStyle = row.colour;
      for (const it of row.items) {
        if (it.x1 < min || it.x0 > max) continue;
        const px0 = u.valToPos(it.x0, 'x', true), px1 = u.valToPos(it.x1, 'x', true);
        if (it.point || px1 - px0 < 2 * dpr) {
          ctx.fillRect(px0 - dpr, yc - h * 0.32, 2 * dpr, h * 0.64);
        } else {
          ctx.globalAlpha = 0.75;
          ctx.fillRect(px0, yc - h * 0.25, px1 - px0, h * 0.5);
          ctx.globalAlpha = 1;
        }
      }
    });
    ctx.restore();
  }

  // The element under a click (within 5 px), shown on the map; false when none.
  function pick(rows, u, left, top) {
    const r = Math.floor(top / (u.bbox.height / (window.devicePixelRatio || 1)) * rows.length);
    const row = rows[r];
    if (!row) return false;
    const x = u.posToVal(left, 'x');
    const tol = Math.abs(u.posToVal(left + 5, 'x') - x);
    let best = null, bestD = Infinity;
    for (const it of row.items) {
      const d = x < it.x0 ? it.x0 - x : (x > it.x1 ? x - it.x1 : 0);
      if (d < bestD) { bestD = d; best = it; }
    }
    if (!best || bestD > tol) return false;
    RA.showElement(best.e);
    return true;
  }

  function bandChart(D, C, target, baseOptions) {
    const rows = rowItems(D, C);
    const opts = baseOptions('Places along the chain (click one to show it on the map)',
      rows.length * 20 + 50, [{label: 'places', show: false}], [{
        scale: 'y', size: 125, gap: 4,
        splits: () => rows.map((_, i) => rows.length - i - 0.5),
        values: () => rows.map((row) => row.label + ' (' + row.items.length + ')'),
        grid: {show: false}, ticks: {show: false},
      }]);
    opts.scales.y = {auto: false, range: [0, rows.length]};
    opts.legend = {show: false};
    opts.hooks.draw = [(u) => drawRows(u, rows)];
    const data = [[0, C.length], [null, null]];
    const u = new uPlot(opts, data, target);
    u.railoddRows = rows;
    return {u, pick: (uu, left, top) => pick(rows, uu, left, top)};
  }

  RA.bandChart = bandChart;
})(window.RailoddApp = window.RailoddApp || {});
