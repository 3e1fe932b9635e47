// railodd report app: shared helpers. Every app file is an IIFE that adds to one
// namespace object (window.RailoddApp), because the files are concatenated into a
// single classic <script> with no module system.
(function (RA) {
  'use strict';

  // Builds an element; attrs keys starting with "on" become listeners so tables
  // and controls can be written as data instead of imperative DOM calls.
  function el(tag, attrs, children) {
    const node = document.createElement(tag);
    if (attrs) {
      for (const k of Object.keys(attrs)) {
        const v = attrs[k];
        if (v == null || v === false) continue;
        if (k.startsWith('on')) node.addEventListener(k.slice(2), v);
        else if (k === 'class') node.className = v;
        else if (k === 'text') node.textContent = v;
        else if (k === 'style') node.style.cssText = v;
        else node.setAttribute(k, v === true ? '' : v);
      }
    }
    append(node, children);
    return node;
  }

  function append(node, children) {
    if (children == null) return node;
    if (!Array.isArray(children)) children = [children];
    for (const c of children) {
      if (c == null || c === false) continue;
      node.appendChild(typeof c === 'object' ? c : document.createTextNode(String(c)));
    }
    return node;
  }

  const ESC = {'&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;'};
  // Popups take HTML strings (Leaflet); everything from the data goes through this.
  function esc(s) {
    return String(s == null ? '' : s).replace(/[&<>"']/g, (c) => ESC[c]);
  }

  function num(v, digits) {
    if (v == null || v === '' || (typeof v === 'number' && !isFinite(v))) return '–';
    if (typeof v !== 'number') return String(v);
    return v.toLocaleString('en-US', {maximumFractionDigits: digits == null ? 2 : digits,
                                      minimumFractionDigits: 0});
  }

  function km(m) { return m == null ? '–' : num(m / 1000, 3) + ' km'; }
  function pct(r) { return r == null ? '–' : num(r * 100, 1) + ' %'; }

  // Attribute values come as numbers, strings or booleans; long floats are noise.
  function fmtValue(v) {
    if (v == null) return '–';
    if (typeof v === 'number') return num(v, Math.abs(v) >= 100 ? 1 : 3);
    return String(v);
  }

  // A fixed qualitative palette, so the same class gets the same colour on every redraw.
  const PALETTE = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b',
    '#e377c2', '#17becf', '#bcbd22', '#7f7f7f', '#393b79', '#ad494a', '#637939', '#e7ba52'];

  // Ordered colour ramp (cool → hot) for classes that have a natural order.
  function ramp(t) {
    const stops = [[44, 123, 182], [0, 166, 202], [0, 204, 188], [144, 235, 157],
      [249, 208, 87], [242, 158, 46], [215, 25, 28]];
    t = Math.max(0, Math.min(1, t)) * (stops.length - 1);
    const i = Math.min(stops.length - 2, Math.floor(t)), f = t - i;
    const c = stops[i].map((a, j) => Math.round(a + (stops[i + 1][j] - a) * f));
    return 'rgb(' + c.join(',') + ')';
  }

  // A table with a row cap and a "show more" button: Cologne has 170k elements and
  // thousands of scenarios, and building all rows up front would stall the page.
  function cappedTable(headers, rowCount, rowFn, opts) {
    opts = opts || {};
    const step = opts.step || 200;
    const tbody = el('tbody');
    const table = el('table', {class: 'grid' + (opts.cls ? ' ' + opts.cls : '')},
      [el('thead', null, el('tr', null, headers.map((h) => el('th', {text: h})))), tbody]);
    const more = el('button', {class: 'more'});
    let shown = 0;
    function fill() {
      const end = Math.min(rowCount, shown + step);
      const frag = document.createDocumentFragment();
      for (let i = shown; i < end; i++) frag.appendChild(rowFn(i));
      tbody.appendChild(frag);
      shown = end;
      more.textContent = 'show more (' + num(rowCount - shown, 0) + ' left)';
      more.style.display = shown < rowCount ? '' : 'none';
    }
    more.addEventListener('click', fill);
    fill();
    return el('div', {class: 'table-wrap'}, [table, more]);
  }

  function tr(cells, attrs) {
    return el('tr', attrs, cells.map((c) => (c instanceof Node && (c.tagName === 'TD' || c.tagName === 'TH')) ? c :
      el('td', null, c instanceof Node ? c : (c == null ? '–' : String(c)))));
  }

  function section(id, title, children) {
    return el('section', {id: id, class: 'panel'}, [el('h2', {text: title})].concat(children || []));
  }

  function kv(pairs) {
    return el('dl', {class: 'kv'}, pairs.flatMap(([k, v]) => [el('dt', {text: k}),
      el('dd', null, v instanceof Node ? v : (v == null ? '–' : String(v)))]));
  }

  function link(text, fn, title) {
    return el('a', {href: '#', class: 'maplink', title: title || 'show on the map',
      onclick: (e) => { e.preventDefault(); fn(); }}, text);
  }

  Object.assign(RA, {el, append, esc, num, km, pct, fmtValue, PALETTE, ramp, cappedTable, tr,
    section, kv, link});
})(window.RailoddApp = window.RailoddApp || {});
