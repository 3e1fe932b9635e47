// The map's own layer panel. Leaflet's layers control is not used: collapsed it loads
// images/layers.png, which does not exist in an offline single-file report.
(function (RA) {
  'use strict';
  const el = RA.el;

  function overlayRow(map, o) {
    const box = el('input', {type: 'checkbox', checked: o.on,
      onchange: () => {
        if (box.checked) { map.addLayer(o.layer); if (o.point) RA.raisePoints(RA.layers); }
        else map.removeLayer(o.layer);
        if (o.onToggle) o.onToggle(box.checked);
      }});
    if (o.on) map.addLayer(o.layer);
    // Layers shown from elsewhere (a test, a table link) keep the box truthful.
    map.on('layeradd layerremove', (e) => { if (e.layer === o.layer) box.checked = map.hasLayer(o.layer); });
    return el('label', {class: 'ov'}, [box, o.colour ? RA.swatch(o.colour) : null, o.label,
      o.count != null ? el('span', {class: 'lgkm', text: RA.num(o.count, 0)}) : null]);
  }

  function colourSelect(D, initial, onChange) {
    const modes = RA.colourModes(D);
    const sel = el('select', {id: 'colour-by', onchange: () => onChange(sel.value || null)},
      [el('option', {value: '', text: 'plain'})].concat(Object.keys(modes).map((k) =>
        el('option', {value: k, text: modes[k].label, selected: k === initial}))));
    return sel;
  }

  function nodeLegend(layer) {
    if (!layer) return null;
    const stops = [0, 0.25, 0.5, 0.75, 1].map((t) => RA.ramp(t)).join(',');
    return el('div', {class: 'noderamp'}, [
      el('span', {class: 'rampbar', style: 'background:linear-gradient(to right,' + stops + ')'}),
      el('span', {text: '0 … ≥' + RA.num(layer.railoddScale, 2) + ' m'})]);
  }

  // overlays: [{label, layer, on, colour, count, point, onToggle}] in drawing order.
  function buildPanel(D, map, overlays, initialMode, onColour) {
    const Panel = L.Control.extend({
      options: {position: 'topright'},
      onAdd: function () {
        const div = el('div', {class: 'leaflet-bar mappanel'}, [
          el('div', {class: 'ph', text: 'Colour tracks by'}),
          colourSelect(D, initialMode, onColour),
          el('div', {id: 'legend'}),
          el('div', {class: 'ph', text: 'Layers'}),
        ].concat(overlays.map((o) => overlayRow(map, o))));
        const nodes = overlays.find((o) => o.key === 'nodes');
        if (nodes) div.appendChild(nodeLegend(nodes.layer));
        L.DomEvent.disableClickPropagation(div);
        L.DomEvent.disableScrollPropagation(div);
        return div;
      },
    });
    const panel = new Panel();
    panel.addTo(map);
    return panel;
  }

  RA.buildPanel = buildPanel;
})(window.RailoddApp = window.RailoddApp || {});
