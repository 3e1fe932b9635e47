// Popup contents (HTML strings, as Leaflet wants them). Every value from the data is
// escaped. A track popup also lists the ODD stretches that hold at the clicked s,
// which is what a reader usually wants to know about a place.
(function (RA) {
  'use strict';
  const esc = RA.esc;

  let allByRoad = null;
  function elementsOnRoad(roadIndex) {
    if (!allByRoad) allByRoad = RA.elementsByRoad(RA.data, RA.data.kinds.map((k) => k.id));
    return allByRoad.get(roadIndex) || [];
  }

  function rows(pairs) {
    return '<table class="pt">' + pairs.filter((p) => p[1] != null && p[1] !== '').map(([k, v]) =>
      '<tr><th>' + esc(k) + '</th><td>' + esc(v) + '</td></tr>').join('') + '</table>';
  }

  function sText(v) { return v == null ? '' : RA.num(v, 2) + ' m'; }

  function trackPopup(road, s) {
    const D = RA.data;
    const here = elementsOnRoad(road.index).filter((e) => !D.kindOf(e).point &&
      s >= Math.min(e[2], e[3]) - 0.01 && s <= Math.max(e[2], e[3]) + 0.01);
    const track = here.length ? here[0][4] : null;
    let html = '<div class="pop"><b>Rail track</b> road ' + esc(road.id) +
      rows([['road id', road.id], ['s', sText(s)], ['road length', sText(road.length)],
        ['junction', road.junction !== '-1' ? road.junction : ''],
        ['profile track', track], ['OSM', road.osm]]);
    if (here.length) {
      html += '<div class="popsub">ODD here</div><table class="pt">';
      for (const e of here.slice(0, 14)) {
        const k = D.kindOf(e);
        const vals = k.attrs.map((a, j) => [a, e[7][j]]).filter((p) => p[1] != null)
          .slice(0, 3).map(([a, v]) => a + ' ' + RA.fmtValue(v)).join(', ');
        html += '<tr><th>' + esc(k.path.split('/').pop()) + '</th><td>' + esc(vals) + '</td></tr>';
      }
      html += '</table>';
    }
    return html + '</div>';
  }

  function roadPopup(road) {
    return '<div class="pop"><b>Road</b> ' + esc(road.id) +
      rows([['road id', road.id], ['length', sText(road.length)], ['OSM', road.osm]]) + '</div>';
  }

  function elementPopup(e) {
    const D = RA.data, k = D.kindOf(e), road = D.roads[e[1]];
    const point = k.point || e[2] === e[3];
    const attrs = k.attrs.map((a, j) => [a, RA.fmtValue(e[7][j])]).filter((p) => p[1] !== '–');
    return '<div class="pop"><b>' + esc(k.path) + '</b><div class="kid">' + esc(k.id) + '</div>' +
      rows(attrs) + rows([['road id', road ? road.id : '(not in the map)'],
        ['s', point ? sText(e[2]) : sText(e[2]) + ' … ' + sText(e[3])],
        ['track', e[4]], ['chainage', point ? sText(e[5]) : sText(e[5]) + ' … ' + sText(e[6])],
        ['OSM', RA.osmOf(D, e)],
        ['direction', e[9] & 1 ? 'against road s' : '']]) + '</div>';
  }

  // Violation rows of the spec check carry their own place and values.
  function violationPopup(v) {
    const road = RA.data.roads[v.road];
    return '<div class="pop"><b>Outside the declared ODD</b>' + rows([['element', v.element],
      ['attribute', v.attribute], ['value', RA.fmtValue(isNaN(+v.value) ? v.value : +v.value) +
        (v.unit ? ' ' + v.unit : '')], ['constraint', v.constraint], ['note', v.note],
      ['road id', road ? road.id : ''], ['s', v.point ? sText(v.s0) : sText(v.s0) + ' … ' + sText(v.s1)],
      ['track', v.track], ['chainage', sText(v.ch0)], ['OSM', v.osm]]) + '</div>';
  }

  function showElement(e) {
    const point = RA.data.kindOf(e).point;
    RA.focus(e[1], e[2], point ? null : e[3], elementPopup(e));
  }

  Object.assign(RA, {trackPopup, roadPopup, elementPopup, violationPopup, showElement});
})(window.RailoddApp = window.RailoddApp || {});
