// Colouring the tracks by an ODD attribute: which element kinds feed each mode, how an
// element maps to a class, the class order (taken from the profile summary where it
// has one, so the legend reads from mild to severe) and the colours.
(function (RA) {
  'use strict';

  const LANDUSE = {urban: '#e63946', suburban: '#f4a261', rural: '#a7c957', industrial: '#6d597a',
    forest: '#2d6a4f', agricultural: '#e9c46a', water: '#4895ef'};

  function keysOf(obj) { return obj && typeof obj === 'object' ? Object.keys(obj) : []; }

  // Fixes the class list and the colours once all classes present are known.
  function finish(D, mode, colourFor) {
    const seen = new Map();
    for (const id of mode.kinds) {
      for (const e of D.elementsOf(id)) {
        const c = mode.classOf(e);
        if (c == null) continue;
        const len = Math.abs(e[6] - e[5]);
        seen.set(c, (seen.get(c) || 0) + len);
      }
    }
    const order = mode.order.filter((c) => seen.has(c));
    for (const c of seen.keys()) if (!order.includes(c)) order.push(c);
    mode.classes = order.map((c, i) => ({cls: c, km: seen.get(c) / 1000,
      colour: colourFor(c, i, order.length)}));
    const byCls = new Map(mode.classes.map((c) => [c.cls, c.colour]));
    mode.colour = (c) => byCls.get(c) || '#888';
    return mode;
  }

  function ordered(i, n, reverse) {
    const t = n > 1 ? i / (n - 1) : 0.5;
    return RA.ramp(reverse ? 1 - t : t);
  }

  function radiusMode(D) {
    const classes = keysOf(D.summary && D.summary.curve_km_by_radius);
    const mode = {label: 'Curve radius class',
      kinds: ['sc.geo.hz.straight', 'sc.geo.hz.transition', 'sc.geo.hz.curve'],
      order: ['straight', 'transition'].concat(classes.map((c) => 'R ' + c)),
      classOf: (e) => {
        const id = D.kindOf(e).id;
        if (id === 'sc.geo.hz.straight') return 'straight';
        if (id === 'sc.geo.hz.transition') return 'transition';
        const c = D.attr(e, 'radius_class');
        return c == null ? null : 'R ' + c;
      }};
    return finish(D, mode, (c, i, n) => c === 'straight' ? '#7fa7c9' :
      c === 'transition' ? '#b388eb' : ordered(i - 2, n - 2, true));
  }

  function classMode(D, label, kinds, attr, order, reverse) {
    const mode = {label, kinds, order,
      classOf: (e) => { const v = D.attr(e, attr); return v == null ? null : String(v); }};
    return finish(D, mode, (c, i, n) => ordered(i, n, reverse));
  }

  // Few distinct limits: one class per value; many: the profile's speed classes.
  function speedMode(D) {
    const values = new Set();
    for (const e of D.elementsOf('op.speed.limit')) {
      const v = D.attr(e, 'maxspeed');
      if (v != null) values.add(v);
    }
    if (values.size > 0 && values.size <= 12) {
      const sorted = Array.from(values).sort((a, b) => a - b);
      const mode = {label: 'Speed limit', kinds: ['op.speed.limit'],
        order: sorted.map((v) => RA.num(v, 0) + ' km/h'),
        classOf: (e) => { const v = D.attr(e, 'maxspeed'); return v == null ? null : RA.num(v, 0) + ' km/h'; }};
      return finish(D, mode, (c, i, n) => ordered(i, n, false));
    }
    return classMode(D, 'Speed limit class', ['op.speed.limit'], 'maxspeed_class',
      keysOf(D.summary && D.summary.speed_km_by_class), false);
  }

  let cache = null;
  function colourModes(D) {
    if (cache) return cache;
    const landuseKinds = D.kindsMatching(/landuse/);
    const all = {
      radius: radiusMode(D),
      gradient: classMode(D, 'Gradient class', ['sc.geo.vt.gradient'], 'gradient_class',
        keysOf(D.summary && D.summary.gradient_km_by_class), false),
      speed: speedMode(D),
      tracks: classMode(D, 'Track count', ['sc.lay.tracks'], 'tracks_class',
        ['single', 'double', 'multiple'], false),
    };
    if (landuseKinds.length) {
      const lu = {label: 'Land use', kinds: landuseKinds,
        order: keysOf(D.summary && D.summary.landuse_km_by_kind),
        classOf: (e) => { const v = D.attr(e, 'kind'); return v == null ? null : String(v); }};
      all.landuse = finish(D, lu, (c, i) => LANDUSE[c] || RA.PALETTE[i % RA.PALETTE.length]);
    }
    cache = {};
    for (const k of Object.keys(all)) if (all[k].classes.length) cache[k] = all[k];
    return cache;
  }

  // The legend lives in the layer panel; it is rewritten on every colour change.
  function renderLegend(mode) {
    const box = document.getElementById('legend');
    if (!box) return;
    box.textContent = '';
    if (!mode) {
      RA.append(box, el('div', {class: 'lg'}, [swatch(RA.TRACK_COLOUR), 'rail track']));
      return;
    }
    for (const c of mode.classes) {
      RA.append(box, el('div', {class: 'lg'}, [swatch(c.colour), c.cls,
        el('span', {class: 'lgkm', text: RA.num(c.km, 1) + ' km'})]));
    }
    RA.append(box, el('div', {class: 'lg'}, [swatch('#b8bec6'), 'no data']));
  }

  const el = RA.el;
  function swatch(colour) { return el('span', {class: 'sw', style: 'background:' + colour}); }

  Object.assign(RA, {colourModes, renderLegend, swatch});
})(window.RailoddApp = window.RailoddApp || {});
