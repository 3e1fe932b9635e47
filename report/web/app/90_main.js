// Page layout and start-up: header, navigation, the sections in page order, and the
// window.railoddReport handle the browser test inspects once everything is drawn.
(function (RA) {
  'use strict';
  const el = RA.el;

  // Colouring a big network by class means one sub-line per ODD stretch; above this
  // many elements the map starts plain and the reader picks a colouring.
  const COLOUR_BY_DEFAULT_MAX_ELEMENTS = 60000;

  function header(D) {
    const m = D.meta || {}, inp = D.input || {}, od = inp.opendrive || {};
    const facts = [['route', m.route], ['length', RA.km(m.length_m)], ['profile tracks', RA.num(m.tracks, 0)],
      ['roads', od.roads != null ? RA.num(od.roads, 0) + ' (' + RA.num(od.rail_roads, 0) + ' rail)' : null],
      ['junctions', od.junctions != null ? RA.num(od.junctions, 0) : null],
      ['dropped', RA.num(inp.dropped, 0)], ['repairs', RA.num(inp.repairs, 0)],
      ['railodd', m.railodd], ['OpenDRIVE', m.odr_version]];
    const nav = [['map-section', 'Map'], ['charts-section', 'Chainage charts'], ['odd-section', 'ODD'],
      ['scenarios-section', 'Scenarios'], ['fit-section', 'Fit quality']];
    return el('header', {class: 'top'}, [
      el('h1', {text: m.title || 'railodd report'}),
      el('div', {class: 'facts'}, facts.filter((f) => f[1] != null && f[1] !== '–' || f[0] === 'dropped' || f[0] === 'repairs')
        .map(([k, v]) => el('span', {class: 'fact'}, [el('b', {text: k + ' '}), String(v)]))),
      el('nav', null, nav.map(([id, label]) => el('a', {href: '#' + id, text: label})))]);
  }

  function mapSection(D) {
    const s = RA.section('map-section', 'Map', [el('div', {id: 'map'})]);
    return s;
  }

  function chartSection(D) {
    const box = el('div', {id: 'charts'});
    const sel = el('select', {id: 'chain-select', onchange: () => RA.drawCharts(D, +sel.value, box)},
      D.chains.map((c, i) => el('option', {value: String(i),
        text: (c.label || 'chain ' + (i + 1)) + ' — ' + RA.km(c.length) + ' (' + c.parts.length + ' tracks)'})));
    return {box, node: RA.section('charts-section', 'Chainage charts', [
      el('div', {class: 'controls'}, [el('label', null, ['Chain ', sel]),
        el('span', {class: 'muted', text: ' Drag on a chart to zoom all of them, double-click to reset; click to show the place on the map.'})]),
      box])};
  }

  function buildMap(D, layers) {
    const map = RA.createMap(D, 'map');
    RA.map = map;
    layers.tracks = L.featureGroup();
    layers.roads = L.featureGroup();
    RA.drawRoads(D, layers.roads);
    const overlays = [{key: 'roads', label: 'Other roads', colour: '#8d8d8d', layer: layers.roads, on: true,
      count: layers.roads.getLayers().length}];
    RA.drawFeatures(D, layers, overlays);
    // Canvas paints in the order layers join the map: roads, structures, tracks, points.
    const firstPoint = overlays.findIndex((o) => o.point);
    overlays.splice(firstPoint < 0 ? overlays.length : firstPoint, 0, {key: 'tracks',
      label: 'Rail tracks', colour: RA.TRACK_COLOUR, layer: layers.tracks, on: true});
    if (D.spec && D.spec.violations && D.spec.violations.length) {
      layers.violations = RA.violationLayer(D);
      overlays.push({key: 'violations', label: 'Outside the declared ODD', colour: '#d00000',
        layer: layers.violations, on: true, count: layers.violations.getLayers().length, point: true});
    }
    if (D.scenarios) {
      layers.scenarios = RA.anchorLayer(D, D.scenarios);
      overlays.push({key: 'scenarios', label: 'Scenario anchors', colour: '#8ecae6',
        layer: layers.scenarios, on: true, count: layers.scenarios.getLayers().length, point: true});
    }
    layers.nodes = RA.nodeLayer(D);
    if (layers.nodes) {
      overlays.push({key: 'nodes', label: 'Mapped nodes (residual)', colour: null, layer: layers.nodes,
        on: false, count: layers.nodes.railoddCount});
    }
    const mode = D.elements.length <= COLOUR_BY_DEFAULT_MAX_ELEMENTS && RA.colourModes(D).radius ? 'radius' : null;
    RA.drawTracks(D, layers.tracks, mode);
    RA.buildPanel(D, map, overlays, mode, (m) => {
      RA.drawTracks(D, layers.tracks, m);
      RA.raisePoints(layers);
    });
    RA.renderLegend(mode ? RA.colourModes(D)[mode] : null);
    RA.raisePoints(layers);
    return map;
  }

  // A failing section reports its error (console.error fails the browser test) but
  // does not take the rest of the report down with it.
  function guarded(name, box, fn) {
    try { return fn(); } catch (err) {
      console.error('railodd report: ' + name + ' failed:', err);
      if (box) box.appendChild(el('p', {class: 'error', text: name + ' could not be drawn: ' + err.message}));
      return null;
    }
  }

  function start() {
    const t0 = performance.now();
    const raw = JSON.parse(document.getElementById('railodd-data').textContent);
    const D = RA.decode(raw);
    RA.data = D;
    const app = document.getElementById('app');
    const layers = {};
    RA.layers = layers;
    const charts = chartSection(D);
    const odd = RA.section('odd-section', 'ODD summary');
    const scen = RA.section('scenarios-section', 'Scenarios');
    const fit = RA.section('fit-section', 'Fit quality');
    RA.append(app, [header(D), el('main', null, [mapSection(D), charts.node, odd, scen, fit])]);
    guarded('map', app, () => buildMap(D, layers));
    guarded('charts', charts.box, () => RA.drawCharts(D, 0, charts.box));
    guarded('ODD summary', odd, () => RA.drawOdd(D, odd));
    guarded('scenarios', scen, () => RA.drawScenarios(D, scen));
    const hist = guarded('fit quality', fit, () => RA.drawFit(D, fit));
    window.addEventListener('resize', () => { RA.resizeCharts(); RA.map.invalidateSize(); });
    window.railoddReport = {ready: true, map: RA.map, layers, charts: RA.charts, histogram: hist,
      data: D, chain: () => RA.currentChain, app: RA, build_ms: Math.round(performance.now() - t0)};
    document.body.dataset.ready = '1';
  }

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})(window.RailoddApp = window.RailoddApp || {});
