// The Leaflet map: rail roads (one feature per road, optionally coloured by an ODD
// attribute), other roads, and the shared "show this place" helper the tables use.
(function (RA) {
  'use strict';

  const TRACK_COLOUR = '#1d3557';
  const NO_DATA_COLOUR = '#b8bec6';

  function createMap(D, container) {
    const map = L.map(container, {preferCanvas: true, zoomSnap: 0.25, attributionControl: false,
      worldCopyJump: false});
    // A wide click tolerance: tracks are 3 px lines and the report is used with a mouse.
    RA.renderer = L.canvas({padding: 0.3, tolerance: 5});
    if (D.meta && D.meta.tiles) {
      // The only case where the page loads anything: the user asked for a basemap.
      let host = D.meta.tiles;
      try { host = new URL(D.meta.tiles.replace(/[{}]/g, '')).host; } catch (e) { /* keep the template */ }
      L.control.attribution({prefix: false}).addTo(map);
      L.tileLayer(D.meta.tiles, {maxZoom: 19, attribution: 'basemap: ' + RA.esc(host)}).addTo(map);
    }
    const b = D.bounds;
    if (b && isFinite(b[0])) map.fitBounds([[b[1], b[0]], [b[3], b[2]]], {padding: [10, 10]});
    else map.setView([0, 0], 2);
    L.control.scale({imperial: false}).addTo(map);
    return map;
  }

  // Elements of the given kinds per road index, for colouring and for popups.
  function elementsByRoad(D, kindIds) {
    const byRoad = new Map();
    for (const id of kindIds) {
      for (const e of D.elementsOf(id)) {
        if (e[1] < 0) continue;
        let list = byRoad.get(e[1]);
        if (!list) byRoad.set(e[1], list = []);
        list.push(e);
      }
    }
    return byRoad;
  }

  function onTrackClick(ev) {
    const D = RA.data, road = D.roads[this.railoddRoad];
    const ll = ev.latlng || L.latLng(road.lat[0], road.lon[0]);
    const s = RA.nearestS(road, ll.lat, ll.lng);
    L.popup({maxWidth: 420}).setLatLng(ll).setContent(RA.trackPopup(road, s)).openOn(RA.map);
  }

  // One feature per rail road: a polyline when uncoloured, else a feature group of the
  // road's coloured stretches over a grey base, so counting features counts roads.
  function trackFeature(road, mode, byRoad) {
    const base = {renderer: RA.renderer, weight: 3, opacity: 0.95};
    let feature;
    const list = mode && byRoad.get(road.index);
    if (!list || !list.length) {
      feature = L.polyline(RA.latlngs(road), Object.assign({}, base,
        {color: mode ? NO_DATA_COLOUR : TRACK_COLOUR}));
    } else {
      const parts = [L.polyline(RA.latlngs(road), Object.assign({}, base, {color: NO_DATA_COLOUR}))];
      for (const e of list) {
        const cls = mode.classOf(e);
        if (cls == null) continue;
        parts.push(L.polyline(RA.slice(road, e[2], e[3]), Object.assign({}, base,
          {color: mode.colour(cls), weight: 4})));
      }
      feature = L.featureGroup(parts);
    }
    feature.railoddRoad = road.index;
    feature.on('click', onTrackClick);
    return feature;
  }

  function drawTracks(D, group, modeKey) {
    const mode = modeKey ? RA.colourModes(D)[modeKey] : null;
    const byRoad = mode ? elementsByRoad(D, mode.kinds) : new Map();
    group.clearLayers();
    RA.trackByRoad = new Map();
    for (const road of D.roads) {
      if (!road.rail) continue;
      const f = trackFeature(road, mode, byRoad);
      RA.trackByRoad.set(road.index, f);
      group.addLayer(f);
    }
    RA.renderLegend(mode);
  }

  function drawRoads(D, group) {
    for (const road of D.roads) {
      if (road.rail) continue;
      const f = L.polyline(RA.latlngs(road), {renderer: RA.renderer, color: '#8d8d8d', weight: 1.5,
        opacity: 0.8});
      f.bindPopup(() => RA.roadPopup(road));
      group.addLayer(f);
    }
  }

  // Moves the map to a road stretch (or point) and opens a popup there; used by every
  // "show on the map" link in the tables and by clicks on the charts.
  function focus(roadIndex, s0, s1, html) {
    const D = RA.data, map = RA.map, road = D.roads[roadIndex];
    if (!road || !map) return;
    showMap();
    const pos = RA.positionAt(road, s1 == null ? s0 : (s0 + s1) / 2);
    if (s1 != null && Math.abs(s1 - s0) > 50) {
      const pts = RA.slice(road, s0, s1);
      RA.highlight(pts);
      map.fitBounds(L.latLngBounds(pts), {maxZoom: 17, padding: [40, 40], animate: false});
    } else {
      RA.highlight(null);
      map.setView(pos, Math.max(map.getZoom(), 16), {animate: false});
    }
    L.popup({maxWidth: 420}).setLatLng(pos).setContent(html || RA.trackPopup(road, s0))
      .openOn(map);
  }

  // Brings the map on screen for a link further down the page, unless it is mostly visible.
  function showMap() {
    const mapEl = document.getElementById('map');
    if (!mapEl) return;
    const r = mapEl.getBoundingClientRect(), vh = window.innerHeight;
    const visible = Math.max(0, Math.min(r.bottom, vh) - Math.max(r.top, 0));
    if (visible < 0.5 * Math.min(r.height, vh)) document.getElementById('map-section').scrollIntoView({block: 'start'});
  }

  let hl = null;
  function highlight(pts) {
    if (hl) { RA.map.removeLayer(hl); hl = null; }
    if (pts) {
      hl = L.polyline(pts, {renderer: RA.renderer, color: '#ffd400', weight: 9, opacity: 0.7,
        interactive: false}).addTo(RA.map);
    }
  }

  // A marker for a chart position (chain x → road, s), replaced on every click.
  let cursorMarker = null;
  function markChainPlace(road, s, html) {
    const r = RA.data.roads[road];
    if (!r) return;
    if (cursorMarker) RA.map.removeLayer(cursorMarker);
    cursorMarker = L.circleMarker(RA.positionAt(r, s), {renderer: RA.renderer, radius: 9,
      color: '#000', weight: 2, fillColor: '#ffd400', fillOpacity: 0.8}).addTo(RA.map);
    focus(road, s, null, html);
  }

  Object.assign(RA, {createMap, drawTracks, drawRoads, focus, showMap, highlight, markChainPlace,
    elementsByRoad, TRACK_COLOUR});
})(window.RailoddApp = window.RailoddApp || {});
