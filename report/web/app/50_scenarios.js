// Scenario coverage: selection figures, coverage ratios, the ODD item × template
// matrix, pairwise coverage per template, gaps, the play results and a map layer
// with every scenario's anchor.
(function (RA) {
  'use strict';
  const el = RA.el, tr = RA.tr;

  function figure(value, label) {
    return el('div', {class: 'fig'}, [el('div', {class: 'fv', text: value}),
      el('div', {class: 'fl', text: label})]);
  }

  function ratioBar(r) {
    const w = Math.round(80 * Math.max(0, Math.min(1, r || 0)));
    return el('td', null, [el('span', {class: 'bar' + (r < 1 ? ' warn' : ''), style: 'width:' + w + 'px'}),
      ' ' + RA.pct(r)]);
  }

  function figures(S) {
    const sel = S.selection || {};
    const out = [figure(RA.num(S.count, 0), 'scenarios (' + (S.strategy || sel.strategy || '') + ')')];
    if (sel.pairwise_scenarios != null) out.push(figure(RA.num(sel.pairwise_scenarios, 0), 'pairwise'));
    if (sel.full_factorial_scenarios != null) out.push(figure(RA.num(sel.full_factorial_scenarios, 0), 'full factorial'));
    if (sel.ratio_to_pairwise != null) out.push(figure(RA.pct(sel.ratio_to_pairwise), 'of pairwise'));
    if (S.route) out.push(figure(RA.pct(S.route.ratio), 'route items covered (' + S.route.covered + ' / ' + S.route.items + ')'));
    if (S.spec) out.push(figure(RA.pct(S.spec.ratio), 'spec items covered (' + S.spec.covered + ' / ' + S.spec.items + ', ' + S.spec.hostable + ' hostable)'));
    if (S.criticality && S.criticality.can_stop != null) {
      const c = S.criticality;
      out.push(figure(RA.num(c.can_stop, 0) + ' / ' + RA.num(c.can_stop + c.cannot_stop, 0), 'train can stop in sight'));
    }
    if (S.play && S.play.summary) {
      const p = S.play.summary;
      out.push(figure(RA.num(p.passed, 0) + ' / ' + RA.num(p.scenarios, 0), 'played and passed'));
    }
    return el('div', {class: 'figs'}, out);
  }

  // Per template: rows, anchors, pairwise coverage and, when the set was assessed,
  // how many scenarios leave the train room to stop (coverage.json criticality).
  function templatesTable(S) {
    const crit = (S.criticality && S.criticality.templates) || {};
    const hasCrit = Object.keys(crit).length > 0;
    const head = ['template', 'scenarios', 'anchors', 'pairs covered / feasible', 'pairwise coverage']
      .concat(hasCrit ? ['can stop', 'cannot stop'] : []);
    return el('table', {class: 'grid'}, [el('thead', null, tr(head.map((h) => el('th', {text: h})))),
      el('tbody', null, (S.templates || []).map((t) => {
        const id = t.template || t.id, c = crit[id] || {};
        const pairs = RA.num(t.pairs_covered, 0) + ' / ' + RA.num(t.pairs_feasible, 0) +
          (t.pairs_infeasible ? ' (' + RA.num(t.pairs_infeasible, 0) + ' infeasible)' : '');
        return tr([id, RA.num(t.rows, 0), RA.num(t.anchors, 0) + (t.anchors_infeasible ?
          ' (' + RA.num(t.anchors_infeasible, 0) + ' infeasible)' : ''), pairs, ratioBar(t.ratio)]
          .concat(hasCrit ? [RA.num(c.can_stop, 0), RA.num(c.cannot_stop, 0)] : []));
      }))]);
  }

  function matrixTable(S) {
    const M = S.matrix;
    if (!M || !M.items || !M.items.length) return el('p', {class: 'muted', text: 'No coverage matrix.'});
    let max = 1;
    for (const row of M.counts) for (const c of row) if (c > max) max = c;
    const head = tr([el('th', {text: 'ODD item'}), el('th', {text: 'on route'})].concat(
      M.templates.map((t) => el('th', {class: 'rot'}, el('span', {text: t})))));
    const rows = M.items.map((it, i) => {
      const counts = M.counts[i] || [];
      const total = counts.reduce((a, b) => a + b, 0);
      const label = it.element.split('/').slice(-2).join(' / ') +
        (it.attribute ? ' · ' + it.attribute + ' = ' + it['class'] : '');
      const cls = total === 0 ? (it.on_route > 0 || it.in_spec ? 'uncovered' : 'absent') : '';
      return tr([el('td', {title: it.element, text: label + (it.in_spec ? ' ★' : '')}),
        RA.num(it.on_route, 0)].concat(counts.map((c) => el('td', {class: 'cell',
        style: c ? 'background:rgba(29,53,87,' + (0.12 + 0.75 * c / max).toFixed(2) + ');color:' +
          (c / max > 0.5 ? '#fff' : '#000') : '', text: c ? String(c) : ''}))), {class: cls});
    });
    return el('div', {class: 'table-wrap matrix'}, [el('table', {class: 'grid small'},
      [el('thead', null, head), el('tbody', null, rows)]),
    el('p', {class: 'muted', text: '★ in the declared ODD; highlighted rows: on the route or in the spec but exercised by no scenario.'})]);
  }

  function gapsTable(S) {
    const g = S.gaps || [];
    if (!g.length) return el('p', {class: 'muted', text: 'No coverage gaps.'});
    return RA.cappedTable(['element', 'attribute', 'class', 'in', 'on route', 'reason'], g.length,
      (i) => tr([g[i].element, g[i].attribute, g[i]['class'], g[i]['in'], RA.num(g[i].on_route, 0),
        g[i].reason]), {cls: 'gaps'});
  }

  // A scenario the player could not run is neither passed nor failed.
  function playState(p) {
    if (!p) return null;
    if (p.ran === false) return 'not run';
    return p.passed ? 'passed' : 'failed';
  }

  function crit(sc) {
    const c = sc.play && sc.play.criticality;
    if (!c) return {};
    const actors = c.actors || [];
    const minOf = (k) => actors.reduce((m, a) => a[k] != null && a[k] < m ? a[k] : m, Infinity);
    return {canStop: c.can_stop, stop: c.stopping_distance_m, sight: c.sight_distance_m,
      minDist: minOf('min_distance_m'), ttc: minOf('ttc_at_onset_s')};
  }

  function scenarioPopup(sc) {
    const c = crit(sc), p = sc.play;
    const rows = [['template', sc.template], ['anchor', sc.element], ['track', sc.track],
      ['chainage', RA.num(sc.chainage, 1) + ' m']];
    if (p) {
      const st = playState(p);
      rows.push(['play', st !== 'failed' ? st : 'FAILED' + (p.failed_checks && p.failed_checks.length ?
        ': ' + p.failed_checks.join('; ') : '')], ['can stop', c.canStop == null ? '' : (c.canStop ? 'yes' : 'no')],
      ['stopping / sight', RA.num(c.stop, 0) + ' m / ' + RA.num(c.sight, 0) + ' m'],
      ['min distance', isFinite(c.minDist) ? RA.num(c.minDist, 1) + ' m' : ''],
      ['TTC at onset', isFinite(c.ttc) ? RA.num(c.ttc, 1) + ' s' : '']);
    }
    return '<div class="pop"><b>' + RA.esc(sc.id) + '</b><div class="stext">' + RA.esc(sc.text) +
      '</div><table class="pt">' + rows.map(([k, v]) => '<tr><th>' + RA.esc(k) + '</th><td>' +
      RA.esc(v) + '</td></tr>').join('') + '</table></div>';
  }

  function anchorLayer(D, S) {
    const group = L.featureGroup();
    for (const sc of S.list || []) {
      const road = D.roads[sc.road];
      if (!road) continue;
      const failed = playState(sc.play) === 'failed';
      const m = L.circleMarker(RA.positionAt(road, sc.s), {renderer: RA.renderer, radius: 6,
        color: failed ? '#d00000' : '#003049', weight: 2, fillColor: failed ? '#ff8fa3' : '#8ecae6',
        fillOpacity: 0.7});
      m.railoddScenario = sc;
      m.bindPopup(() => scenarioPopup(sc), {maxWidth: 420});
      group.addLayer(m);
    }
    return group;
  }

  function showScenario(sc) { RA.focus(sc.road, sc.s, null, scenarioPopup(sc)); }

  function playTable(D, S) {
    const list = S.list || [];
    const yes = (b) => b == null ? '–' : (b ? 'yes' : 'no');
    return RA.cappedTable(['scenario', 'template', 'play', 'can stop', 'stopping (m)', 'sight (m)',
      'min distance (m)', 'TTC at onset (s)'], list.length, (i) => {
      const sc = list[i], c = crit(sc), st = playState(sc.play);
      return tr([RA.link(sc.id, () => showScenario(sc)), sc.template,
        el('td', {class: st === 'passed' ? 'pass' : st === 'failed' ? 'fail' : '', text: st || '–'}), yes(c.canStop),
        RA.num(c.stop, 1), RA.num(c.sight, 1), isFinite(c.minDist) ? RA.num(c.minDist, 1) : '–',
        isFinite(c.ttc) ? RA.num(c.ttc, 1) : '–'], {class: st === 'failed' ? 'flag' : ''});
    }, {step: 100});
  }

  function drawScenarios(D, box) {
    const S = D.scenarios;
    if (!S) { box.appendChild(el('p', {class: 'muted', text: 'No scenario set given (--scenarios).'})); return; }
    const play = S.play ? ' — played in ' + (S.play.player || '') + ' ' + (S.play.version || '') : '';
    RA.append(box, [el('p', {class: 'muted', text: (S.dir || '') + play}), figures(S),
      el('h3', {text: 'Pairwise coverage per template'}), templatesTable(S),
      el('h3', {text: 'Coverage matrix: ODD items × templates'}), matrixTable(S),
      el('h3', {text: 'Gaps'}), gapsTable(S),
      el('h3', {text: 'Scenarios' + (S.play ? ' and play results' : '')}), playTable(D, S)]);
  }

  Object.assign(RA, {drawScenarios, anchorLayer, showScenario});
})(window.RailoddApp = window.RailoddApp || {});
