// Chainage charts (uPlot): curvature, elevation/gradient, cant/speed on one shared x
// axis in metres along the selected chain. Zooming one chart zooms all of them.
(function (RA) {
  'use strict';
  const el = RA.el;
  const SYNC_KEY = 'railodd-chain';

  // Aligns several [xs, ys] series on one sorted x array. Rows of other series get
  // undefined (uPlot spans those) while explicit nulls stay gaps. Rows at 0 and at the
  // chain length make uPlot's automatic x range exactly [0, length].
  function alignTable(length, list) {
    const rows = [[0, -1, undefined], [length, -1, undefined]];
    list.forEach(([xs, ys], si) => { for (let i = 0; i < xs.length; i++) rows.push([xs[i], si, ys[i]]); });
    rows.sort((a, b) => a[0] - b[0]);
    const x = new Array(rows.length);
    const cols = list.map(() => new Array(rows.length));
    for (let i = 0; i < rows.length; i++) {
      const [xv, si, yv] = rows[i];
      x[i] = Math.max(0, Math.min(length, xv));
      if (si >= 0) cols[si][i] = yv;
    }
    cols.forEach(widenGaps);
    return [x].concat(cols);
  }

  // uPlot clips a gap between the rows next to its null; those can be other series'
  // rows, so every row between the two defined values around a null becomes null.
  function widenGaps(col) {
    let lastDefined = -1, inGap = false;
    for (let i = 0; i < col.length; i++) {
      if (col[i] === null) inGap = true;
      else if (col[i] !== undefined) {
        if (inGap) for (let j = lastDefined + 1; j < i; j++) col[j] = null;
        inGap = false;
        lastDefined = i;
      }
    }
  }

  let syncing = false;
  // Keeps every chart's x range equal to the one the user just changed.
  function syncScale(u, key) {
    if (key !== 'x' || syncing) return;
    syncing = true;
    const {min, max} = u.scales.x;
    for (const other of RA.charts) {
      if (other !== u && (other.scales.x.min !== min || other.scales.x.max !== max)) {
        other.setScale('x', {min, max});
      }
    }
    syncing = false;
  }

  function chartWidth() {
    const box = document.getElementById('charts');
    return Math.max(400, (box ? box.clientWidth : 1200) - 8);
  }

  function mValue(u, v) { return v == null ? '–' : RA.num(v, 1) + ' m'; }

  function baseOptions(title, height, series, axes) {
    return {
      title, width: chartWidth(), height,
      cursor: {sync: {key: SYNC_KEY, setSeries: false}, drag: {x: true, y: false}},
      scales: {x: {time: false}},
      series: [{label: 'chain position', value: mValue}].concat(series),
      axes: [xAxis()].concat(axes),
      hooks: {setScale: [syncScale]},
    };
  }

  // Long chains read better in km; short ones keep metres.
  let xInKm = false;
  function xAxis() {
    return {label: 'position along the chain (' + (xInKm ? 'km' : 'm') + ')', labelSize: 20, size: 40,
      values: (u, splits) => splits.map((v) => xInKm ? RA.num(v / 1000, 1) : RA.num(v, 0))};
  }

  function fixed(d) { return (u, v) => v == null ? '–' : RA.num(v, d); }

  function curvatureChart(D, C, target) {
    const S = RA.chainSeries;
    const [fx, fy] = S.curvatureSeries(D, C);
    const [nx, ny] = S.nodeCurvatureSeries(D, C);
    const data = alignTable(C.length, [[fx, fy.map((k) => k == null ? null : k * 1000)],
      [nx, ny.map((k) => k * 1000)]]);
    const opts = baseOptions('Curvature (1/km, + left along the chain)', 220, [
      {label: 'fitted', stroke: '#1d3557', width: 1.5, value: fixed(3), spanGaps: false},
      {label: 'mapped nodes', stroke: '#e76f51', paths: () => null, value: fixed(3),
        points: {show: true, size: 4, fill: '#e76f51', stroke: '#e76f51'}},
    ], [{label: '1/km', labelSize: 20, size: 60}]);
    return new uPlot(opts, data, target);
  }

  // Gradient elements carry an unsigned value and a direction relative to the track's
  // chainage; on the chart it is signed along growing chain x.
  function signedGradient(D, C) {
    return (e) => {
      const g = D.attr(e, 'gradient');
      if (g == null) return null;
      const dir = D.attr(e, 'direction');
      const sign = dir === 'falling' ? -1 : 1;
      return sign * Math.abs(g) * C.dir(e[4]);
    };
  }

  // Whether any track's heights come from data (a DEM or mapped `ele`): a map
  // without is flat at 0 m, which is no elevation to draw.
  function hasElevation(D) {
    const src = (D.input || {}).elevation_sources || {};
    return (src.dem || 0) + (src.osm_ele || 0) + (src.interpolated || 0) > 0;
  }

  function elevationChart(D, C, target) {
    if (!hasElevation(D)) {
      target.classList.add('chart-note');
      target.appendChild(el('p', {text: 'Elevation and gradient: no elevation data (convert with --dem)'}));
      return null;
    }
    const S = RA.chainSeries;
    const data = alignTable(C.length, [S.elevationSeries(D, C),
      S.stepSeries(D, C, 'sc.geo.vt.gradient', signedGradient(D, C))]);
    const opts = baseOptions('Elevation (m) and gradient (‰)', 200, [
      {label: 'elevation', scale: 'z', stroke: '#2a9d8f', width: 1.5, value: fixed(1)},
      {label: 'gradient', scale: 'g', stroke: '#e63946', width: 1, value: fixed(2)},
    ], [{scale: 'z', label: 'm', labelSize: 20, size: 60},
      {scale: 'g', side: 1, label: '‰', labelSize: 20, size: 50, grid: {show: false}}]);
    return new uPlot(opts, data, target);
  }

  function cantSpeedChart(D, C, target) {
    const S = RA.chainSeries;
    const data = alignTable(C.length, [
      S.stepSeries(D, C, 'sc.geo.cant', (e) => D.attr(e, 'cant')),
      S.stepSeries(D, C, 'op.speed.limit', (e) => D.attr(e, 'maxspeed'))]);
    const opts = baseOptions('Cant (mm) and speed limit (km/h)', 200, [
      {label: 'cant', scale: 'mm', stroke: '#6a4c93', width: 1.5, value: fixed(0)},
      {label: 'speed limit', scale: 'kmh', stroke: '#f77f00', width: 1.5, value: fixed(0)},
    ], [{scale: 'mm', label: 'mm', labelSize: 20, size: 60},
      {scale: 'kmh', side: 1, label: 'km/h', labelSize: 20, size: 50, grid: {show: false}}]);
    return new uPlot(opts, data, target);
  }

  // A click (not a drag-zoom) on a chart shows that chain position on the map.
  function clickToMap(u, C, band) {
    let down = null;
    u.over.addEventListener('mousedown', (e) => { down = [e.clientX, e.clientY]; });
    u.over.addEventListener('click', (e) => {
      if (down && Math.abs(e.clientX - down[0]) + Math.abs(e.clientY - down[1]) > 4) return;
      const x = u.posToVal(e.offsetX, 'x');
      if (band && band.pick(u, e.offsetX, e.offsetY)) return;
      const loc = C.locate(x);
      if (loc) RA.markChainPlace(loc.road, loc.s, RA.trackPopup(RA.data.roads[loc.road], loc.s));
    });
  }

  function drawCharts(D, chainIndex, box) {
    for (const u of RA.charts) u.destroy();
    RA.charts.length = 0;
    box.textContent = '';
    const chain = D.chains[chainIndex];
    if (!chain) { box.appendChild(el('p', {text: 'No chain of tracks to chart.'})); return; }
    const C = RA.buildChain(D, chain);
    RA.currentChain = C;
    xInKm = C.length > 20000;
    const makers = [curvatureChart, elevationChart, cantSpeedChart];
    for (const make of makers) {
      const div = el('div', {class: 'chart'});
      box.appendChild(div);
      const u = make(D, C, div);
      if (!u) continue; // a note instead of a chart
      RA.charts.push(u);
      clickToMap(u, C, null);
    }
    const div = el('div', {class: 'chart'});
    box.appendChild(div);
    const band = RA.bandChart(D, C, div, baseOptions);
    RA.charts.push(band.u);
    clickToMap(band.u, C, band);
  }

  function resizeCharts() {
    const w = chartWidth();
    for (const u of RA.charts) u.setSize({width: w, height: u.height});
  }

  RA.charts = [];
  Object.assign(RA, {drawCharts, resizeCharts, alignTable});
})(window.RailoddApp = window.RailoddApp || {});
