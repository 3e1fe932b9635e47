// ODD summary: the profile summary by class, every element kind with its count and
// length (each opens a lazily built, capped element table), and the spec check.
(function (RA) {
  'use strict';
  const el = RA.el, tr = RA.tr;

  function title(key) { return key.replace(/_/g, ' '); }

  // Summary values are numbers, or objects of class → km/count; "_km" keys are lengths.
  function summaryBlock(summary) {
    const scalars = [], groups = [];
    for (const [k, v] of Object.entries(summary || {})) {
      if (v && typeof v === 'object') groups.push([k, v]); else scalars.push([title(k), RA.num(v, 3)]);
    }
    const cards = groups.map(([k, obj]) => {
      const unit = /km/.test(k) ? ' km' : '';
      const entries = Object.entries(obj);
      const maxV = Math.max(1e-9, ...entries.map(([, v]) => typeof v === 'number' ? v : 0));
      return el('div', {class: 'card'}, [el('h4', {text: title(k)}),
        el('table', {class: 'grid small'}, el('tbody', null, entries.map(([c, v]) => tr([
          title(c), typeof v === 'number' ? RA.num(v, 3) + (unit && c !== 'count' ? unit : '') : String(v),
          el('td', null, typeof v === 'number' ? el('span', {class: 'bar',
            style: 'width:' + Math.round(60 * v / maxV) + 'px'}) : null)]))))]);
    });
    return el('div', null, [RA.kv(scalars), el('div', {class: 'cards'}, cards)]);
  }

  function kindStats(D) {
    const stats = D.kinds.map((k) => ({kind: k, count: 0, m: 0}));
    for (const e of D.elements) {
      const st = stats[e[0]];
      st.count++;
      if (!st.kind.point) st.m += Math.abs(e[6] - e[5]);
    }
    return stats.filter((s) => s.count).sort((a, b) => a.kind.path.localeCompare(b.kind.path));
  }

  function elementTable(D, kind) {
    const list = D.elementsOf(kind.id);
    const headers = ['#', 'road', 's (m)', 'track', 'chainage (m)'].concat(kind.attrs, ['OSM', '']);
    return RA.cappedTable(headers, list.length, (i) => {
      const e = list[i], road = D.roads[e[1]];
      const s = kind.point ? RA.num(e[2], 1) : RA.num(e[2], 1) + ' – ' + RA.num(e[3], 1);
      const ch = kind.point ? RA.num(e[5], 1) : RA.num(e[5], 1) + ' – ' + RA.num(e[6], 1);
      return tr([String(i + 1), road ? road.id : '–', s, String(e[4]), ch]
        .concat(e[7].map(RA.fmtValue), [RA.osmOf(D, e),
          road ? RA.link('map', () => RA.showElement(e)) : '']));
    }, {step: 100});
  }

  function kindsTable(D) {
    const detail = el('div', {class: 'detail'});
    const stats = kindStats(D);
    const rows = stats.map((st) => tr([
      RA.link(st.kind.path, () => {
        detail.textContent = '';
        RA.append(detail, [el('h4', {text: st.kind.path + ' (' + st.kind.id + ')'}),
          elementTable(D, st.kind)]);
        detail.scrollIntoView({block: 'nearest'});
      }, 'list these elements'),
      st.kind.id, RA.num(st.count, 0), st.kind.point ? '' : RA.num(st.m / 1000, 3)]));
    return el('div', null, [
      el('table', {class: 'grid'}, [el('thead', null, tr(['ODD element', 'id', 'count', 'km'].map(
        (h) => el('th', {text: h})))), el('tbody', null, rows)]),
      detail]);
  }

  function violationRow(D, v) {
    const road = D.roads[v.road];
    return tr([v.element, v.attribute, RA.fmtValue(isNaN(+v.value) ? v.value : +v.value) +
      (v.unit ? ' ' + v.unit : ''), v.constraint, road ? road.id : '–',
      v.point ? RA.num(v.s0, 1) : RA.num(v.s0, 1) + ' – ' + RA.num(v.s1, 1), v.osm,
      road ? RA.link('map', () => RA.focus(v.road, v.s0, v.point ? null : v.s1,
        RA.violationPopup(v))) : '']);
  }

  function specBlock(D) {
    const sp = D.spec;
    if (!sp) return el('p', {class: 'muted', text: 'No declared ODD was checked (run with --odd-spec).'});
    const verdict = el('span', {class: 'badge ' + (sp.passed ? 'ok' : 'bad'),
      text: sp.passed ? 'INSIDE the declared ODD' : 'OUTSIDE the declared ODD'});
    const v = sp.violations || [];
    return el('div', {id: 'spec'}, [
      el('h3', null, ['Declared ODD: ', sp.name || '', ' ', verdict]),
      RA.kv([['source', sp.source], ['elements checked', RA.num(sp.elements_checked, 0)],
        ['elements outside', RA.num(sp.elements_outside, 0)],
        ['violations', RA.num(sp.violations_total != null ? sp.violations_total : v.length, 0) +
          (sp.violations_total > v.length ? ' (' + RA.num(v.length, 0) + ' listed)' : '')],
        ['stretches', sp.stretches ? RA.num(sp.stretches.length, 0) : null]]),
      v.length ? RA.cappedTable(['element', 'attribute', 'value', 'constraint', 'road', 's (m)',
        'OSM', ''], v.length, (i) => violationRow(D, v[i]), {cls: 'violations'}) : null]);
  }

  function drawOdd(D, box) {
    RA.append(box, [el('h3', {text: 'Profile summary'}), summaryBlock(D.summary),
      el('h3', {text: 'Elements by kind'}), kindsTable(D), specBlock(D)]);
  }

  RA.drawOdd = drawOdd;
})(window.RailoddApp = window.RailoddApp || {});
