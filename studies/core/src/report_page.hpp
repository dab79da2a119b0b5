#pragma once
// The style sheet and script of the report page (report.cpp). The script only filters and shows
// what the page already contains: without it every study, table and figure is still there.
#include <string_view>

namespace soma::studies::detail {

inline constexpr std::string_view kReportCss = R"css(
:root { --ink:#1d232b; --muted:#5f6b78; --rule:#d9d4c7; --paper:#fbfaf6; --card:#ffffff;
  --pass:#1f7a45; --pass-bg:#e6f4ea; --fail:#b3261e; --fail-bg:#fdecea; --accent:#2c5c8a; }
* { box-sizing: border-box; }
html { background: var(--paper); }
body { margin: 0; color: var(--ink); font: 15px/1.5 "Charter", "Georgia", "DejaVu Serif", serif; }
main { max-width: 1180px; margin: 0 0 0 330px; padding: 28px 36px 60px; }
aside.sidebar { position: fixed; top: 0; left: 0; bottom: 0; width: 310px; overflow-y: auto;
  background: #f3f1ea; border-right: 1px solid var(--rule); padding: 14px 14px 40px;
  font: 13.5px/1.4 "DejaVu Sans", Arial, sans-serif; }
aside.sidebar h2 { font-size: 14px; margin: 14px 0 6px; border-bottom: 1px solid var(--rule); }
aside.sidebar .brand { font-weight: 700; font-size: 15px; margin-bottom: 8px; }
.filters label { display: block; margin: 6px 0 2px; color: var(--muted); font-size: 12px; }
.filters input[type=search], .filters select { width: 100%; font: inherit; padding: 4px 6px;
  border: 1px solid var(--rule); border-radius: 3px; background: #fff; }
#match-count { margin: 8px 0; color: var(--muted); font-size: 12.5px; }
#match-count b { color: var(--ink); }
button.clear { font: inherit; font-size: 12px; margin-top: 6px; padding: 2px 8px; cursor: pointer; }
nav.toc details { margin: 2px 0; }
nav.toc summary { cursor: pointer; font-weight: 600; }
nav.toc ul { list-style: none; padding-left: 8px; margin: 3px 0 8px; font-weight: normal; }
nav.toc ul li { margin: 1px 0; font-size: 12px; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
nav.toc .top a { display: block; margin: 2px 0; }
@media (max-width: 900px) { aside.sidebar { position: static; width: auto; border-right: 0; }
  main { margin: 0; padding: 16px; } }
.chapter-summary { font-size: 13.5px; color: var(--muted); margin: -4px 0 10px; }
.chapter-summary b { color: var(--ink); }
table.errata { width: 100%; font-size: 13px; table-layout: fixed; }
table.errata th { text-align: left; font: 600 11.5px "DejaVu Sans", Arial, sans-serif; color: var(--muted);
  text-transform: uppercase; border-bottom: 1px solid var(--ink); padding: 4px 6px; }
table.errata td { border-bottom: 1px solid #ece8de; padding: 5px 6px; vertical-align: top; overflow-wrap: anywhere; }
table.errata col.e-label { width: 70px; } table.errata col.e-where { width: 170px; }
table.errata col.e-found { width: 26%; } table.errata col.e-study { width: 210px; }
.errata .label { font-weight: 700; white-space: nowrap; }
.links { font-size: 12.5px; margin: 0 0 6px; color: var(--muted); }
.links a { margin-right: 10px; }
.tag { display: inline-block; font: 600 10.5px/1 "DejaVu Sans", Arial, sans-serif; padding: 3px 5px;
  border-radius: 3px; background: #efe9d8; color: #6b5a2a; margin-left: 4px; }
ul.notes table.md { font-size: 12.5px; margin: 4px 0; }
table.md th, table.md td { border: 1px solid var(--rule); padding: 2px 8px; text-align: left; }
table.md th { background: #f3f1ea; }
#lightbox { position: fixed; inset: 0; background: rgba(20,22,26,.88); z-index: 10; display: none;
  overflow: auto; padding: 40px 20px 20px; text-align: center; }
#lightbox.open { display: block; }
#lightbox img { max-width: none; background: #fff; }
#lightbox .bar { position: fixed; top: 0; left: 0; right: 0; padding: 8px 14px; color: #eee;
  background: rgba(0,0,0,.6); font: 13px "DejaVu Sans", Arial, sans-serif; text-align: left; }
#lightbox .bar a { color: #9cc9ff; margin-left: 12px; }
#lightbox .bar button { float: right; font: inherit; cursor: pointer; }
.fig-links { font-size: 12px; }
.fig-links a { margin-right: 8px; }
[hidden] { display: none !important; }
h1, h2, h3 { font-family: "Helvetica Neue", "Liberation Sans", "DejaVu Sans", Arial, sans-serif;
  font-weight: 600; letter-spacing: -0.01em; }
h1 { font-size: 26px; margin: 0 0 2px; }
h2 { font-size: 19px; margin: 34px 0 10px; padding-bottom: 4px; border-bottom: 2px solid var(--ink); }
h3 { font-size: 15px; margin: 0; font-family: "DejaVu Sans Mono", "Liberation Mono", monospace; }
a { color: var(--accent); text-decoration: none; }
a:hover { text-decoration: underline; }
code, .mono { font-family: "DejaVu Sans Mono", "Liberation Mono", Menlo, monospace; font-size: 12.5px; }
.subtitle { color: var(--muted); margin: 0 0 18px; font-style: italic; }
.verdict { display: inline-block; font: 600 14px/1 "DejaVu Sans", Arial, sans-serif;
  padding: 9px 14px; border-radius: 4px; letter-spacing: .04em; margin-bottom: 14px; }
.verdict.pass { background: var(--pass-bg); color: var(--pass); border: 1px solid #a8d5b5; }
.verdict.fail { background: var(--fail-bg); color: var(--fail); border: 1px solid #f0b4ae; }
table { border-collapse: collapse; }
table.meta { font-size: 13.5px; margin-bottom: 8px; }
table.meta th { text-align: left; color: var(--muted); font-weight: normal; padding: 2px 18px 2px 0;
  vertical-align: top; white-space: nowrap; }
table.meta td { padding: 2px 0; }
.counts b.pass { color: var(--pass); } .counts b.fail { color: var(--fail); }
.failed-list { background: var(--fail-bg); border: 1px solid #f0b4ae; border-left: 5px solid var(--fail);
  padding: 10px 18px 12px; margin: 18px 0; border-radius: 3px; }
.failed-list h2 { border: 0; margin: 0 0 6px; color: var(--fail); font-size: 16px; padding: 0; }
.failed-list ul { margin: 0; padding-left: 18px; }
.failed-list li { margin: 3px 0; }
.failed-list .why { color: var(--muted); font-size: 13.5px; }
nav.toc ol { padding-left: 20px; margin: 0; }
nav.toc > ol > li { margin: 6px 0; font-weight: 600; }
nav.toc ul { list-style: none; padding-left: 4px; margin: 3px 0 8px; font-weight: normal; }
nav.toc ul li { margin: 1px 0; font-size: 14px; }
nav.toc .tally { color: var(--muted); font-weight: normal; font-size: 13px; margin-left: 6px; }
nav.toc .id { font-family: "DejaVu Sans Mono", monospace; font-size: 12.5px; }
.badge { display: inline-block; min-width: 40px; text-align: center; font: 700 11px/1 "DejaVu Sans", Arial,
  sans-serif; letter-spacing: .06em; padding: 4px 6px; border-radius: 3px; vertical-align: 1px; }
.badge.pass { background: var(--pass); color: #fff; }
.badge.fail { background: var(--fail); color: #fff; }
nav.toc .badge { min-width: 34px; padding: 2px 4px; font-size: 9.5px; margin-right: 6px; }
.chapter-tally { float: right; font: normal 13px "DejaVu Sans", Arial, sans-serif; color: var(--muted);
  padding-top: 5px; }
article.study { background: var(--card); border: 1px solid var(--rule); border-left: 5px solid var(--pass);
  border-radius: 3px; padding: 12px 16px 10px; margin: 14px 0 18px; }
article.study.fail { border-color: #f0b4ae; border-left-color: var(--fail); background: #fffafa;
  box-shadow: 0 0 0 1px #f6d3cf; }
.study-head { display: flex; align-items: baseline; gap: 10px; flex-wrap: wrap; }
.study-title { margin: 2px 0 0; font-size: 15.5px; }
.study-meta { margin: 2px 0 8px; color: var(--muted); font-size: 13px; }
.error { background: var(--fail-bg); border: 1px solid #f0b4ae; color: var(--fail); padding: 6px 10px;
  margin: 8px 0; border-radius: 3px; font-size: 13.5px; white-space: pre-wrap; }
table.checks { width: 100%; font-size: 13px; margin: 6px 0 4px; table-layout: fixed; }
table.checks th { text-align: left; white-space: nowrap; font: 600 11.5px "DejaVu Sans", Arial, sans-serif; color: var(--muted);
  text-transform: uppercase; letter-spacing: .04em; border-bottom: 1px solid var(--ink); padding: 4px 6px; }
table.checks td { border-bottom: 1px solid #ece8de; padding: 5px 6px; vertical-align: top;
  overflow-wrap: anywhere; }
table.checks td.num { text-align: right; white-space: nowrap; }
table.checks td.value { font-family: "DejaVu Sans Mono", "Liberation Mono", monospace; font-size: 11.5px; }
table.checks tr.fail td { background: var(--fail-bg); }
table.checks tr.fail td.result { color: var(--fail); font-weight: 700; }
table.checks td.result { color: var(--pass); font: 700 11px "DejaVu Sans", Arial, sans-serif; text-align: center; }
table.checks col.c-idx { width: 30px; } table.checks col.c-name { width: 30%; }
table.checks col.c-err { width: 80px; } table.checks col.c-tol { width: 92px; }
table.checks col.c-time { width: 70px; } table.checks col.c-res { width: 50px; }
table.checks td.idx { color: var(--muted); text-align: right; }
table.trade th { white-space: normal; }
table.trade col.t-scalar { width: 150px; } table.trade col.t-n { width: 92px; } table.trade col.t-time { width: 76px; }
table.trade col.t-err { width: 190px; } table.trade col.t-esc { width: 190px; }
ul.notes { margin: 8px 0 4px; padding-left: 20px; font-size: 14px; }
ul.notes li { margin: 2px 0; }
.figures { display: flex; flex-wrap: wrap; gap: 16px; margin: 10px 0 4px; }
figure { margin: 0; max-width: 100%; }
figure img { display: block; max-width: 100%; max-height: 520px; cursor: zoom-in; border: 1px solid var(--rule); background: #fff; }
figcaption { font-size: 13px; color: var(--muted); margin-top: 4px; max-width: 560px; }
.missing { border: 1px dashed var(--rule); color: var(--muted); padding: 18px; font-size: 13px; }
footer { margin-top: 40px; color: var(--muted); font-size: 12.5px; border-top: 1px solid var(--rule);
  padding-top: 8px; }
)css";

inline constexpr std::string_view kReportScript = R"js(
(function () {
  'use strict';
  var $ = function (s, r) { return (r || document).querySelector(s); };
  var $$ = function (s, r) { return Array.prototype.slice.call((r || document).querySelectorAll(s)); };
  var studies = $$('article.study');
  var tocItems = {};
  $$('nav.toc li[data-id]').forEach(function (li) { tocItems[li.getAttribute('data-id')] = li; });

  // Search: lunr (copied next to this page) over ID, title, source, check names, notes and errata.
  var index = null;
  if (window.lunr) {
    index = window.lunr(function () {
      this.ref('id');
      this.field('id', { boost: 10 });
      this.field('title', { boost: 5 });
      this.field('source');
      this.field('body');
      var self = this;
      studies.forEach(function (a) {
        var body = $$('.notes li, td.cname', a).map(function (n) { return n.textContent; }).join(' ');
        self.add({ id: a.dataset.id, title: ($('.study-title', a) || a).textContent,
                   source: a.dataset.source || '', body: body + ' ' + (a.dataset.errata || '') });
      });
    });
  }
  function searchHits(q) {
    q = q.trim();
    if (!q) return null;
    var hits = {}, lq = q.toLowerCase();
    studies.forEach(function (a) { if (a.dataset.id.toLowerCase().indexOf(lq) >= 0) hits[a.dataset.id] = true; });
    if (index) {
      var sets = window.lunr.tokenizer(q).map(function (t) {
        var term = t.toString(), found = {};
        index.query(function (query) {
          query.term(term, { usePipeline: true });
          query.term(term, { usePipeline: false, wildcard: window.lunr.Query.wildcard.TRAILING });
        }).forEach(function (r) { found[r.ref] = true; });
        return found;
      });
      if (sets.length) {
        Object.keys(sets[0]).forEach(function (id) {
          if (sets.every(function (s) { return s[id]; })) hits[id] = true;
        });
      }
    } else {
      studies.forEach(function (a) { if (a.textContent.toLowerCase().indexOf(lq) >= 0) hits[a.dataset.id] = true; });
    }
    return hits;
  }

  var form = { q: $('#f-q'), chapter: $('#f-chapter'), verdict: $('#f-verdict'),
               erratum: $('#f-erratum'), scalar: $('#f-scalar') };
  // The erratum and scalar choices come from the studies themselves.
  (function () {
    var labels = {}, scalars = {};
    studies.forEach(function (a) {
      (a.dataset.errata || '').split(' ').forEach(function (l) { if (l) labels[l] = true; });
      (a.dataset.scalar || '').split(' ').forEach(function (s) { if (s) scalars[s] = true; });
    });
    var natural = function (x, y) { return x.localeCompare(y, 'en', { numeric: true }); };
    Object.keys(labels).sort(natural).forEach(function (l) { form.erratum.add(new Option(l, l)); });
    Object.keys(scalars).sort(natural).forEach(function (s) { form.scalar.add(new Option(s, s)); });
  })();

  function has(list, x) { return (' ' + (list || '') + ' ').indexOf(' ' + x + ' ') >= 0; }
  function apply(updateHash) {
    var hits = searchHits(form.q.value), shown = 0;
    var chapter = form.chapter.value, verdict = form.verdict.value, erratum = form.erratum.value,
        scalar = form.scalar.value;
    studies.forEach(function (a) {
      var ok = (!hits || hits[a.dataset.id]) && (!chapter || a.dataset.chapter === chapter) &&
               (!verdict || a.dataset.verdict === verdict) &&
               (!erratum || (erratum === '*' ? !!a.dataset.errata : has(a.dataset.errata, erratum))) &&
               (!scalar || has(a.dataset.scalar, scalar));
      a.hidden = !ok;
      var li = tocItems[a.dataset.id];
      if (li) li.hidden = !ok;
      if (ok) ++shown;
    });
    $$('section.chapter').forEach(function (s) { s.hidden = !$('article.study:not([hidden])', s); });
    $$('nav.toc details').forEach(function (d) {
      d.hidden = !$('li[data-id]:not([hidden])', d);
      var n = $$('li[data-id]:not([hidden])', d).length;
      var c = $('.shown', d);
      if (c) c.textContent = n;
    });
    var filtering = !!(hits || chapter || verdict || erratum || scalar);
    $$('.hide-when-filtering').forEach(function (e) { e.hidden = filtering; });
    $('#match-count').innerHTML = filtering
      ? '<b>' + shown + '</b> of ' + studies.length + ' studies match'
      : studies.length + ' studies';
    if (filtering) $$('nav.toc details').forEach(function (d) { if (!d.hidden) d.open = true; });
    if (updateHash) {
      var parts = [];
      Object.keys(form).forEach(function (k) {
        if (form[k].value) parts.push(k + '=' + encodeURIComponent(form[k].value));
      });
      history.replaceState(null, '', parts.length ? '#' + parts.join('&') : location.pathname);
    }
  }
  // State in the address: index.html#q=cylindroid&verdict=fail (a study's own anchor is #study-…).
  if (location.hash.indexOf('=') > 0) {
    location.hash.slice(1).split('&').forEach(function (kv) {
      var i = kv.indexOf('='), k = kv.slice(0, i), v = decodeURIComponent(kv.slice(i + 1));
      if (form[k]) form[k].value = v;
    });
  }
  Object.keys(form).forEach(function (k) {
    form[k].addEventListener(k === 'q' ? 'input' : 'change', function () { apply(true); });
  });
  $('#f-clear').addEventListener('click', function () {
    Object.keys(form).forEach(function (k) { form[k].value = ''; });
    apply(true);
  });
  apply(false);

  // Figures open full size in an overlay (the link itself opens the file without script).
  var box = $('#lightbox'), boxImg = $('#lightbox img'), boxCaption = $('#lightbox .caption'),
      boxLink = $('#lightbox a.file');
  function closeBox() { box.classList.remove('open'); boxImg.removeAttribute('src'); }
  document.addEventListener('click', function (ev) {
    var a = ev.target.closest ? ev.target.closest('a.fig') : null;
    if (!a) return;
    ev.preventDefault();
    boxImg.onload = function () { box.setAttribute('data-loaded', boxImg.naturalWidth + 'x' + boxImg.naturalHeight); };
    box.removeAttribute('data-loaded');
    boxImg.src = a.getAttribute('href');
    boxCaption.textContent = a.getAttribute('data-caption') || '';
    boxLink.href = a.getAttribute('href');
    box.classList.add('open');
  });
  box.addEventListener('click', function (ev) { if (ev.target === box || ev.target.tagName === 'BUTTON') closeBox(); });
  document.addEventListener('keydown', function (ev) { if (ev.key === 'Escape') closeBox(); });
  document.documentElement.setAttribute('data-ready', index ? 'lunr' : 'plain');
})();
)js";

inline constexpr std::string_view kViewerHtml = R"html(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>soma — 3-D view</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<style>
html, body { margin: 0; height: 100%; overflow: hidden; background: #fff; font: 13px "DejaVu Sans", Arial, sans-serif; color: #1d232b; }
#bar { position: fixed; top: 0; left: 0; right: 0; padding: 6px 12px; background: rgba(243,241,234,.95);
  border-bottom: 1px solid #d9d4c7; z-index: 2; }
#bar label { margin-right: 12px; white-space: nowrap; }
#bar a { margin-right: 12px; color: #2c5c8a; }
#title { font-weight: 600; margin-right: 16px; }
#view { position: absolute; top: 0; left: 0; right: 0; bottom: 0; }
#msg { position: fixed; bottom: 8px; left: 12px; color: #5f6b78; }
.label { position: absolute; font-size: 12px; pointer-events: none; white-space: nowrap; text-shadow: 0 0 3px #fff; }
</style></head>
<body><div id="bar"><a href="index.html">← report</a><span id="title"></span><span id="groups"></span>
<label><input type="checkbox" id="show-labels" checked> text</label></div>
<div id="view"></div><div id="labels"></div>
<div id="msg">drag: rotate · wheel: zoom · right drag: pan</div>
<script src="three.min.js"></script>
<script src="OrbitControls.js"></script>
<script>
(function () {
  'use strict';
  var params = new URLSearchParams(location.search);
  var file = params.get('scene');
  var msg = document.getElementById('msg');
  function fail(text) { msg.textContent = text; document.documentElement.setAttribute('data-ready', 'failed'); }
  if (!window.THREE) return fail('three.min.js is missing beside this page (Debian package libjs-three).');
  if (!file || !/^figures\/[A-Za-z0-9._-]+\.scene\.js$/.test(file)) return fail('no scene given (viewer.html?scene=figures/….scene.js)');
  window.somaScene = function (data) {
    var view = document.getElementById('view');
    var renderer;
    try {
      renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    } catch (e) { return fail('WebGL is not available: ' + e.message); }
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(view.clientWidth, view.clientHeight);
    renderer.setClearColor(0xffffff, 1);
    view.appendChild(renderer.domElement);
    var scene = new THREE.Scene();
    // The robotics convention: z up.
    var lo = new THREE.Vector3().fromArray(data.bounds[0]), hi = new THREE.Vector3().fromArray(data.bounds[1]);
    if (!isFinite(lo.x) || !isFinite(hi.x)) { lo.set(-1, -1, -1); hi.set(1, 1, 1); }
    var centre = lo.clone().add(hi).multiplyScalar(0.5), size = Math.max(hi.clone().sub(lo).length(), 1e-9);
    var camera = new THREE.PerspectiveCamera(35, view.clientWidth / view.clientHeight, size / 1000, size * 100);
    camera.up.set(0, 0, 1);
    camera.position.copy(centre).add(new THREE.Vector3(1, 0.75, 0.55).normalize().multiplyScalar(1.7 * size));
    scene.add(new THREE.HemisphereLight(0xffffff, 0x777777, 0.75));
    var sun = new THREE.DirectionalLight(0xffffff, 0.55);
    sun.position.set(1, 0.6, 1.4);
    scene.add(sun);
    var colour = function (c) { return new THREE.Color(c[0], c[1], c[2]); };
    var material = function (c, lit) {
      var m = lit ? new THREE.MeshLambertMaterial({ color: colour(c), side: THREE.DoubleSide })
                  : new THREE.LineBasicMaterial({ color: colour(c) });
      if (c[3] < 1) { m.transparent = true; m.opacity = c[3]; m.depthWrite = false; }
      return m;
    };
    var v3 = function (p) { return new THREE.Vector3(p[0], p[1], p[2]); };
    var labels = [];
    var groupsBox = document.getElementById('groups');
    document.getElementById('title').textContent = data.title || file;
    document.title = 'soma — ' + (data.title || file);
    data.groups.forEach(function (g, gi) {
      var group = new THREE.Group();
      (g.tubes || []).forEach(function (t) {
        var path = new THREE.CatmullRomCurve3(t.p.map(v3), !!t.closed, 'catmullrom', 0);
        var n = Math.max(2, t.p.length * (t.p.length > 2 ? 4 : 1));
        if (t.p.length === 2) path = new THREE.LineCurve3(v3(t.p[0]), v3(t.p[1]));
        group.add(new THREE.Mesh(new THREE.TubeBufferGeometry(path, n, t.r, 12, !!t.closed), material(t.c, true)));
      });
      (g.meshes || []).forEach(function (m) {
        var geo = new THREE.BufferGeometry();
        geo.setAttribute('position', new THREE.Float32BufferAttribute([].concat.apply([], m.v), 3));
        geo.setIndex(m.t);
        geo.computeVertexNormals();
        group.add(new THREE.Mesh(geo, material(m.c, true)));
      });
      (g.points || []).forEach(function (p) {
        var geo = new THREE.SphereBufferGeometry(p.r, 16, 12), mat = material(p.c, true);
        p.p.forEach(function (q) { var s = new THREE.Mesh(geo, mat); s.position.copy(v3(q)); group.add(s); });
      });
      (g.lines || []).forEach(function (l) {
        var geo = new THREE.BufferGeometry().setFromPoints(l.p.map(v3));
        group.add(l.closed ? new THREE.LineLoop(geo, material(l.c, false)) : new THREE.Line(geo, material(l.c, false)));
      });
      (g.arrows || []).forEach(function (a) {
        var from = v3(a.from), d = v3(a.to).sub(from), len = d.length();
        if (!(len > 0)) return;
        var head = Math.min(0.25 * len, 6 * a.r);
        var shaft = new THREE.Mesh(new THREE.CylinderBufferGeometry(a.r, a.r, len - head, 12), material(a.c, true));
        var cone = new THREE.Mesh(new THREE.ConeBufferGeometry(2.2 * a.r, head, 16), material(a.c, true));
        var q = new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 1, 0), d.clone().normalize());
        shaft.quaternion.copy(q); cone.quaternion.copy(q);
        shaft.position.copy(from).add(d.clone().multiplyScalar((len - head) / 2 / len));
        cone.position.copy(from).add(d.clone().multiplyScalar((len - head / 2) / len));
        group.add(shaft); group.add(cone);
      });
      (g.labels || []).forEach(function (l) {
        var div = document.createElement('div');
        div.className = 'label';
        div.textContent = l.text;
        div.style.color = colour(l.c).getStyle();
        document.getElementById('labels').appendChild(div);
        labels.push({ at: v3(l.at), div: div, group: group });
      });
      scene.add(group);
      var box = document.createElement('label');
      box.innerHTML = '<input type="checkbox" checked> ';
      box.appendChild(document.createTextNode(g.name));
      box.firstChild.id = 'group-' + gi;
      box.firstChild.addEventListener('change', function (ev) { group.visible = ev.target.checked; draw(); });
      groupsBox.appendChild(box);
    });
    var controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.copy(centre);
    controls.update();
    var showLabels = document.getElementById('show-labels');
    function draw() {
      renderer.render(scene, camera);
      labels.forEach(function (l) {
        var p = l.at.clone().project(camera);
        var on = showLabels.checked && l.group.visible && p.z < 1;
        l.div.style.display = on ? '' : 'none';
        if (on) {
          l.div.style.left = ((p.x + 1) / 2 * view.clientWidth + 4) + 'px';
          l.div.style.top = ((1 - p.y) / 2 * view.clientHeight - 16) + 'px';
        }
      });
    }
    controls.addEventListener('change', draw);
    showLabels.addEventListener('change', draw);
    window.addEventListener('resize', function () {
      renderer.setSize(view.clientWidth, view.clientHeight);
      camera.aspect = view.clientWidth / view.clientHeight;
      camera.updateProjectionMatrix();
      draw();
    });
    draw();
    // For the browser test: how many pixels differ from the white background.
    var gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    var px = new Uint8Array(w * h * 4), ink = 0;
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    for (var i = 0; i < px.length; i += 4) if (px[i] < 240 || px[i + 1] < 240 || px[i + 2] < 240) ++ink;
    document.documentElement.setAttribute('data-ink', String(ink));
    document.documentElement.setAttribute('data-groups', String(data.groups.length));
    document.documentElement.setAttribute('data-ready', 'drawn');
  };
  var s = document.createElement('script');
  s.src = file;
  s.onerror = function () { fail('cannot load ' + file); };
  document.body.appendChild(s);
})();
</script></body></html>
)html";

}  // namespace soma::studies::detail
