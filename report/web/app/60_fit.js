// Fit quality: how far the mapped OSM nodes lie from the fitted alignment (histogram,
// percentiles, noise estimate) and the per-track table, worst first.
(function (RA) {
  'use strict';
  const el = RA.el, tr = RA.tr;

  function histogram(fit, target) {
    const h = fit.histogram || {bin_m: 0.05, counts: []};
    const counts = h.counts || [];
    let last = counts.length - 1;
    while (last > 0 && !counts[last]) last--;
    const xs = [], ys = [];
    for (let i = 0; i <= last; i++) { xs.push((i + 0.5) * h.bin_m); ys.push(counts[i]); }
    if (!xs.length) return null;
    const width = Math.min(900, Math.max(400, (target.parentNode ? target.parentNode.clientWidth : 800) - 20));
    const opts = {
      title: 'Residual of each mapped node to the fitted line', width, height: 220,
      scales: {x: {time: false, range: [0, (last + 1) * h.bin_m]}},
      cursor: {drag: {x: false, y: false}},
      series: [{label: 'residual', value: (u, v) => v == null ? '–' : RA.num(v - h.bin_m / 2, 2) +
        '–' + RA.num(v + h.bin_m / 2, 2) + ' m'},
      {label: 'nodes', stroke: '#1d3557', fill: 'rgba(29,53,87,0.55)', value: (u, v) => RA.num(v, 0),
        paths: uPlot.paths.bars({size: [0.9, 60]}), points: {show: false}}],
      axes: [{label: 'residual (m)', labelSize: 20}, {label: 'nodes', labelSize: 20, size: 60}],
    };
    return new uPlot(opts, [xs, ys], target);
  }

  let wayIndex = null;
  // OSM way id → rail roads built from it, to show a fitted track on the map.
  function roadsOfWays(ways) {
    if (!wayIndex) {
      wayIndex = new Map();
      for (const r of RA.data.roads) {
        if (!r.rail) continue;
        for (const id of r.osm.split(',')) {
          if (!id.startsWith('way:')) continue;
          if (!wayIndex.has(id)) wayIndex.set(id, []);
          wayIndex.get(id).push(r);
        }
      }
    }
    const out = new Set();
    for (const w of String(ways).split(/[ ,;]+/)) {
      const key = w.startsWith('way:') ? w : 'way:' + w;
      for (const r of wayIndex.get(key) || []) out.add(r);
    }
    return Array.from(out);
  }

  function showFitTrack(t) {
    const roads = roadsOfWays(t.osm_ways);
    if (!roads.length) return;
    const pts = [];
    for (const r of roads) for (const p of RA.latlngs(r)) pts.push(p);
    RA.showMap();
    RA.map.fitBounds(L.latLngBounds(pts), {padding: [40, 40], maxZoom: 17, animate: false});
    RA.highlight(pts.length < 20000 ? pts : null);
    L.popup({maxWidth: 420}).setLatLng(pts[Math.floor(pts.length / 2)]).setContent(
      '<div class="pop"><b>Fitted track ' + RA.esc(t.edge) + '</b><table class="pt">' +
      [['OSM ways', t.osm_ways], ['length', RA.num(t.length_m, 1) + ' m'], ['nodes', t.nodes],
        ['rms / p95 / max', RA.num(t.rms_m, 3) + ' / ' + RA.num(t.p95_m, 3) + ' / ' + RA.num(t.max_m, 3) + ' m'],
        ['noise σ', RA.num(t.noise_sigma_m, 3) + ' m'], ['flagged', t.flagged ? 'yes' : 'no'],
        ['roads', roads.map((r) => r.id).join(', ')]]
        .map(([k, v]) => '<tr><th>' + RA.esc(k) + '</th><td>' + RA.esc(v) + '</td></tr>').join('') +
      '</table></div>').openOn(RA.map);
  }

  function tracksTable(fit) {
    const list = (fit.tracks || []).slice().sort((a, b) =>
      (b.flagged ? 1 : 0) - (a.flagged ? 1 : 0) || b.rms_m - a.rms_m);
    const flagged = list.filter((t) => t.flagged).length;
    return el('div', null, [
      el('p', null, [RA.num(flagged, 0) + ' of ' + RA.num(list.length, 0) + ' tracks flagged',
        fit.flag_rule ? ' (' + fit.flag_rule + ')' : '', '; worst first. Click a track to show it.']),
      RA.cappedTable(['edge', 'OSM ways', 'length (m)', 'nodes', 'rms (m)', 'p95 (m)', 'max (m)',
        'noise σ (m)', 'flagged'], list.length, (i) => {
        const t = list[i];
        return tr([RA.link(String(t.edge), () => showFitTrack(t)), t.osm_ways, RA.num(t.length_m, 1),
          RA.num(t.nodes, 0), RA.num(t.rms_m, 3), RA.num(t.p95_m, 3), RA.num(t.max_m, 3),
          RA.num(t.noise_sigma_m, 3), t.flagged ? 'yes' : ''], {class: t.flagged ? 'flag' : ''});
      }, {step: 100})]);
  }

  function drawFit(D, box) {
    const fit = D.fit;
    if (!fit || !fit.available) {
      box.appendChild(el('p', {class: 'muted', text: 'Fit quality not available' +
        (fit && fit.reason ? ': ' + fit.reason : '.')}));
      return null;
    }
    const noise = Object.entries(fit.noise || {}).map(([k, v]) => [k.replace(/_/g, ' '), RA.num(v, 3)]);
    const hist = el('div', {class: 'chart'});
    RA.append(box, [el('div', {class: 'cols'}, [
      el('div', null, [RA.kv([['mapped nodes', RA.num(fit.nodes, 0)],
        ['residual p50', RA.num(fit.residual_p50_m, 3) + ' m'],
        ['residual p95', RA.num(fit.residual_p95_m, 3) + ' m'],
        ['residual max', RA.num(fit.residual_max_m, 3) + ' m'],
        ['farther than ' + RA.num(fit.far_m, 0) + ' m', fit.nodes_far != null && fit.far_m != null ?
          RA.num(fit.nodes_far, 0) + ' nodes (not in the histogram)' : null]].filter((p) => p[1] != null)),
      el('h4', {text: 'Estimated node noise'}), RA.kv(noise)]), hist]),
    el('h3', {text: 'Per track'}), tracksTable(fit)]);
    return histogram(fit, hist);
  }

  Object.assign(RA, {drawFit, showFitTrack});
})(window.RailoddApp = window.RailoddApp || {});
