#!/usr/bin/env node
// Headless-browser check of a railodd HTML report (issue 21).
//
//   node tests/report/check_report.mjs REPORT.html --map MAPDIR [--scenarios DIR]
//        [--screenshot PNG] [--full-page] [--timing]
//
// Opens the report from disk (file://) in Chromium and fails on any console error or
// warning, page error, or request that is not file:// or data:. Once the page says it
// is ready, it compares what is drawn with figures read here, independently of the
// report's embedded data, from the map folder (report.json, map.xodr, odd_profile.json)
// and the scenario folder (manifest.json). Exit code 0 only when every check passes.
import {createRequire} from 'node:module';
import {readFileSync, statSync} from 'node:fs';
import {resolve} from 'node:path';
import {pathToFileURL} from 'node:url';

const require = createRequire(new URL('../../report/web/package.json', import.meta.url));
const puppeteer = require('puppeteer-core');

function usage(msg) {
  if (msg) console.error('check_report: ' + msg);
  console.error('usage: check_report.mjs REPORT.html --map MAPDIR [--scenarios DIR] ' +
    '[--screenshot PNG] [--full-page] [--timing]');
  process.exit(2);
}

function parseArgs(argv) {
  const o = {report: null, map: null, scenarios: null, screenshot: null, fullPage: false, timing: false};
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const next = () => { if (i + 1 >= argv.length) usage(a + ' needs a value'); return argv[++i]; };
    if (a === '--map') o.map = next();
    else if (a === '--scenarios') o.scenarios = next();
    else if (a === '--screenshot') o.screenshot = next();
    else if (a === '--full-page') o.fullPage = true;
    else if (a === '--timing') o.timing = true;
    else if (a === '-h' || a === '--help') usage();
    else if (a.startsWith('--')) usage('unknown option ' + a);
    else if (!o.report) o.report = a;
    else usage('more than one report given');
  }
  if (!o.report) usage('no report given');
  if (!o.map) usage('--map is required');
  return o;
}

// Rail roads of an OpenDRIVE file: roads whose non-centre lanes are all rail or tram.
// A plain text scan is enough for railodd's own output (one <lane .../> tag per lane).
function xodrRailRoads(xml) {
  const ids = [];
  const roadRe = /<road\b([^>]*)>([\s\S]*?)<\/road>/g;
  let m;
  while ((m = roadRe.exec(xml))) {
    const id = (/\bid="([^"]*)"/.exec(m[1]) || [])[1];
    const body = m[2];
    const lanesAt = body.indexOf('<lanes>');
    if (lanesAt < 0) continue;
    const lanes = body.slice(lanesAt, body.indexOf('</lanes>', lanesAt));
    const types = [];
    const laneRe = /<lane\b([^>]*)>/g;
    let l;
    while ((l = laneRe.exec(lanes))) {
      const lid = (/\bid="([^"]*)"/.exec(l[1]) || [])[1];
      if (lid === '0') continue;
      types.push((/\btype="([^"]*)"/.exec(l[1]) || [])[1]);
    }
    if (types.length && types.every((t) => t === 'rail' || t === 'tram')) ids.push(id);
  }
  return ids;
}

// odd_profile.json's elements (format 2: rows of element_columns, the kind
// an index into element_kinds, a null chainage equal to the s beside it) as
// objects, read from the documented format rather than from the page.
function profileElements(profile) {
  if (!profile.element_columns) return profile.elements; // format 1
  return profile.elements.map((row) => {
    const e = Object.fromEntries(profile.element_columns.map((c, i) => [c, row[i]]));
    [e.odd_element, e.id] = profile.element_kinds[e.kind];
    e.chainage_start ??= e.s_start;
    e.chainage_end ??= e.s_end;
    return e;
  });
}

function expectations(opts) {
  const dir = resolve(opts.map);
  const report = JSON.parse(readFileSync(dir + '/report.json', 'utf8'));
  const profile = JSON.parse(readFileSync(dir + '/odd_profile.json', 'utf8'));
  const elements = profileElements(profile);
  const xodrRail = xodrRailRoads(readFileSync(dir + '/map.xodr', 'utf8'));
  // Track lengths from the profile (the largest chainage any element of a track reaches),
  // for a default chain that is not every track end to end.
  const trackLength = new Map();
  for (const e of elements) {
    const c = Math.max(e.chainage_start, e.chainage_end);
    if (!(trackLength.get(e.track) >= c)) trackLength.set(e.track, c);
  }
  const exp = {
    trackLength,
    tracks: profile.route.tracks,
    railRoads: report.opendrive.rail_roads,
    xodrRailRoads: xodrRail.length,
    xodrRailIds: xodrRail,
    length: profile.route.length_m,
    levelCrossings: elements.filter((e) => e.id === 'sc.xing.level').length,
    scenarios: null,
    // Heights from data (a DEM, mapped ele): else the page says so instead of a flat chart.
    elevation: ['dem', 'osm_ele', 'interpolated'].some((k) => (report.vertical.sources[k] || 0) > 0),
  };
  if (opts.scenarios) {
    const man = JSON.parse(readFileSync(resolve(opts.scenarios) + '/manifest.json', 'utf8'));
    exp.scenarios = man.scenarios.length;
  }
  return exp;
}

// Everything the page shows, read from the live Leaflet and uPlot objects.
function inspectPage() {
  const R = window.railoddReport;
  const L_ = R.layers;
  const count = (g) => g ? g.getLayers().length : null;
  return {
    tracks: count(L_.tracks),
    levelCrossings: count(L_.levelCrossings),
    scenarios: count(L_.scenarios),
    chainParts: R.data.chains.length ? R.data.chains[0].parts.map((p) => p[0]) : [],
    charts: R.charts.map((u) => ({title: u.root.querySelector('.u-title') ?
      u.root.querySelector('.u-title').textContent : '', min: u.scales.x.min, max: u.scales.x.max})),
    elevationNote: [...document.querySelectorAll('#charts-section .chart-note')].map((n) => n.textContent).join(' '),
  };
}

// Fires a click on one track feature through Leaflet's API at one of its vertices and
// returns the popup text and the road the feature stands for.
function clickTrack(index) {
  const R = window.railoddReport;
  const feats = R.layers.tracks.getLayers();
  const f = feats[Math.min(index, feats.length - 1)];
  const line = f.getLatLngs ? f : f.getLayers()[0];
  const lls = line.getLatLngs();
  const ll = lls[Math.floor(lls.length / 2)];
  R.map.closePopup();
  f.fire('click', {latlng: ll});
  const pop = document.querySelector('.leaflet-popup-content');
  return {text: pop ? pop.innerText : null, road: R.data.roads[f.railoddRoad].id};
}

async function run(opts) {
  const exp = expectations(opts);
  const problems = [];
  const fail = (msg) => problems.push(msg);
  const bytes = statSync(opts.report).size;
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--headless=new', '--no-sandbox', '--disable-gpu', '--allow-file-access-from-files'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({width: 1400, height: 1000});
    page.on('console', (msg) => {
      const t = msg.type();
      if (t === 'error' || t === 'warn' || t === 'warning' || t === 'assert') {
        fail('console ' + t + ': ' + msg.text());
      }
    });
    page.on('pageerror', (err) => fail('page error: ' + (err && err.message || err)));
    page.on('requestfailed', (req) => fail('request failed: ' + req.url()));
    page.on('request', (req) => {
      const u = req.url();
      if (!u.startsWith('file:') && !u.startsWith('data:')) fail('external request: ' + u);
    });
    // Notes the moment the app marks the page ready, in ms since navigation start.
    await page.evaluateOnNewDocument(() => {
      new MutationObserver((_, obs) => {
        if (document.body && document.body.dataset.ready === '1' && window.__readyAt == null) {
          window.__readyAt = performance.now();
          obs.disconnect();
        }
      }).observe(document, {attributes: true, subtree: true, attributeFilter: ['data-ready']});
    });
    await page.goto(pathToFileURL(resolve(opts.report)).href, {waitUntil: 'load', timeout: 60000});
    await page.waitForFunction(() => document.body && document.body.dataset.ready === '1', {timeout: 60000});
    const readyMs = await page.evaluate(() => window.__readyAt);
    const got = await page.evaluate(inspectPage);
    checkDrawn(exp, got, fail);
    const click = await page.evaluate(clickTrack, 0);
    checkClick(exp, click, fail);
    if (opts.screenshot) await screenshot(page, opts);  // before exercise() moves the map
    const used = await exercise(page);
    if (!used.chartPopup) fail('a click on the curvature chart showed no place on the map');
    await new Promise((r) => setTimeout(r, 200));  // late console messages
    return {exp, got, problems, bytes, readyMs, click, used};
  } finally {
    await browser.close();
  }
}

function checkDrawn(exp, got, fail) {
  if (got.tracks !== exp.railRoads) fail(`track features ${got.tracks} != report.json rail_roads ${exp.railRoads}`);
  if (exp.xodrRailRoads !== exp.railRoads) fail(`map.xodr has ${exp.xodrRailRoads} rail roads, report.json says ${exp.railRoads}`);
  if (!got.charts.length) fail('no charts drawn');
  const elevationChart = got.charts.some((c) => /^Elevation/.test(c.title));
  if (exp.elevation !== elevationChart) {
    fail(`elevation chart ${elevationChart ? 'drawn' : 'missing'}, report.json vertical sources ${exp.elevation ? 'with' : 'without'} data`);
  }
  if (!exp.elevation && !/no elevation data \(convert with --dem\)/.test(got.elevationNote)) {
    fail(`no elevation data, but the page does not say so: "${got.elevationNote}"`);
  }
  // The default chain is every track end to end (the route length) when the profile
  // has few tracks; on a network it is one long line, whose length is summed here from
  // the profile's own track lengths.
  const parts = new Set(got.chainParts);
  let want = exp.length, tol = 0.5;
  exp.chainBasis = 'route length';
  if (parts.size !== exp.tracks) {
    want = got.chainParts.reduce((a, t) => a + (exp.trackLength.get(t) || 0), 0);
    tol = 0.5 + 0.01 * got.chainParts.length;
    exp.chainBasis = `${got.chainParts.length} tracks of the profile`;
  }
  exp.chainLength = want;
  for (const c of got.charts) {
    if (Math.abs(c.max - want) > tol || Math.abs(c.min) > 0.5) {
      fail(`chart "${c.title}" x range [${c.min}, ${c.max}] != [0, ${want}] (${exp.chainBasis})`);
    }
  }
  if (got.levelCrossings !== exp.levelCrossings) {
    fail(`level-crossing markers ${got.levelCrossings} != sc.xing.level elements ${exp.levelCrossings}`);
  }
  if (exp.scenarios != null && got.scenarios !== exp.scenarios) {
    fail(`scenario anchor markers ${got.scenarios} != manifest scenarios ${exp.scenarios}`);
  }
}

function checkClick(exp, click, fail) {
  if (!click.text) { fail('clicking a track opened no popup'); return; }
  if (!exp.xodrRailIds.includes(click.road)) fail(`clicked track's road ${click.road} is not a rail road of map.xodr`);
  if (!new RegExp('\\broad\\s+(id\\s+)?' + click.road.replace(/[.*+?^${}()|[\]\\]/g, '\\$&') + '\\b').test(click.text)) {
    fail(`track popup does not name road ${click.road}: ${click.text.slice(0, 120)}`);
  }
}

// Uses the page the way a reader would (every colouring, every layer toggle, a click on
// a chart and on the band, the first link of each table) so that errors in those paths
// show up as console errors. Returns what it did; the popup checks are the caller's.
async function exercise(page) {
  return page.evaluate(async () => {
    const tick = () => new Promise((r) => setTimeout(r, 0));
    const done = {modes: 0, toggles: 0, links: 0, chartPopup: false};
    const sel = document.getElementById('colour-by');
    if (sel) {
      for (const o of Array.from(sel.options).concat([sel.options[sel.selectedIndex]])) {
        sel.value = o.value; sel.dispatchEvent(new Event('change')); done.modes++; await tick();
      }
    }
    for (const box of document.querySelectorAll('.mappanel input[type=checkbox]')) {
      for (let k = 0; k < 2; k++) { box.click(); done.toggles++; await tick(); }
    }
    const R = window.railoddReport;
    R.map.closePopup();
    const u = R.charts[0];
    if (u) {
      const r = u.over.getBoundingClientRect();
      const at = {clientX: r.left + r.width / 2, clientY: r.top + r.height / 2, bubbles: true};
      // uPlot swallows a click whose mousedown was not where the cursor last moved.
      for (const type of ['mousemove', 'mousedown', 'mouseup', 'click']) {
        u.over.dispatchEvent(new MouseEvent(type, at));
      }
      const pop = document.querySelector('.leaflet-popup-content');
      done.chartPopup = !!pop && /Rail track/.test(pop.textContent);
    }
    for (const sec of ['odd-section', 'scenarios-section', 'fit-section']) {
      const a = document.querySelector('#' + sec + ' a.maplink');
      if (a) { a.click(); done.links++; await tick(); }
    }
    const more = document.querySelector('button.more');
    if (more && more.style.display !== 'none') more.click();
    R.map.closePopup();
    return done;
  });
}

async function screenshot(page, opts) {
  await page.evaluate(() => window.railoddReport.map.closePopup());
  if (opts.fullPage) { await page.screenshot({path: opts.screenshot, fullPage: true}); return; }
  // The top of the page: header, map and the chainage charts.
  const h = await page.evaluate(() => {
    const c = document.getElementById('charts-section');
    return c ? Math.ceil(c.getBoundingClientRect().bottom + window.scrollY + 8) : 1000;
  });
  await page.screenshot({path: opts.screenshot, clip: {x: 0, y: 0, width: 1400, height: Math.min(h, 2400)},
    captureBeyondViewport: true});
}

const opts = parseArgs(process.argv.slice(2));
run(opts).then((r) => {
  if (opts.timing) console.log(JSON.stringify({bytes: r.bytes, ready_ms: Math.round(r.readyMs)}));
  const summary = `tracks ${r.got.tracks}/${r.exp.railRoads} (xodr ${r.exp.xodrRailRoads}), ` +
    `charts ${r.got.charts.length} x-max ${r.got.charts.map((c) => c.max.toFixed(1)).join('/')} vs ${r.exp.chainLength.toFixed(1)} m (${r.exp.chainBasis}), ` +
    `level crossings ${r.got.levelCrossings}/${r.exp.levelCrossings}` +
    (r.exp.scenarios != null ? `, scenario anchors ${r.got.scenarios}/${r.exp.scenarios}` : '') +
    `, track click road ${r.click.road}, exercised ${r.used.modes} colourings, ${r.used.toggles} layer toggles, ` +
    `${r.used.links} table links and a chart click, ready ${Math.round(r.readyMs)} ms`;
  if (r.problems.length) {
    for (const p of r.problems) console.error('FAIL: ' + p);
    console.error('check_report: FAILED (' + r.problems.length + ' problems): ' + summary);
    process.exit(1);
  }
  console.log('check_report: OK: ' + summary);
}).catch((err) => {
  console.error('check_report: FAILED: ' + (err && err.stack || err));
  process.exit(1);
});
