// Runs a scene-graph web page's script outside a browser (node viewer_check.js PAGE.html) and
// prints one JSON report for the C++ test (test_viewer.cpp) to compare with the graph it wrote:
// the pure functions on the embedded data (bounds, pick, search, describe), then the page's UI
// code against a small fake DOM whose canvas counts drawing calls, with a search typed and a
// click on an object. Any exception exits non-zero with its message.
"use strict";
const fs = require("fs");
const vm = require("vm");

const html = fs.readFileSync(process.argv[2], "utf8");
const block = (id, type) => {
  const open = '<script id="' + id + '"' + (type ? ' type="' + type + '"' : "") + ">";
  const a = html.indexOf(open);
  if (a < 0) throw new Error("no script block " + id);
  const b = html.indexOf("</script>", a + open.length);
  return html.slice(a + open.length, b);
};
const dataText = block("ussnav-data", "application/json");
const code = block("ussnav-viewer");
const data = JSON.parse(dataText);
const report = { scripts: (html.match(/<\/script>/g) || []).length };

// ---- the pure part, as a module ----
const mod = { module: { exports: {} } };
vm.runInNewContext(code, mod);
const V = mod.module.exports;
const idx = V.index(data);
report.counts = { nodes: data.nodes.length, edges: data.edges.length, regions: data.regions.length,
  objects: data.objects.length, rooms: data.rooms.length, walls: data.walls.length, goals: data.goals.length,
  trajectory: data.trajectory.length, columns: data.coverage.columns.length };
report.bounds = idx.bounds;
report.title = data.title;
report.episode = data.episode;
// What a click at each object's centre and at each node's centre picks.
report.objectPicks = data.objects.map((o) => {
  const h = V.pick(idx, o.c[0], o.c[1]);
  return h ? [o.id, h.kind, h.item.id] : [o.id, "none", -1];
});
report.nodePicks = data.nodes.map((n) => {
  const h = V.pick(idx, n.c[0], n.c[1]);
  return h ? [n.id, h.kind, h.item.id] : [n.id, "none", -1];
});
// A height band that holds no node centre: no node can be picked.
const above = Object.assign({}, idx, { band: [1e3, 1e3 + 1] });
report.bandPicks = data.nodes.map((n) => { const h = V.pick(above, n.c[0], n.c[1]); return h ? h.kind : "none"; });
const far = V.pick(idx, idx.bounds[2] + 50, idx.bounds[3] + 50);
report.farPick = far ? far.kind : "none";
report.search = {};
for (const q of ["bed", "BED ", "", "no such thing"]) report.search[q] = V.search(data, q).map((o) => o.id);
report.regionLines = data.regions.map((r) => V.describe(idx, { kind: "region", item: r }));
report.objectLines = data.objects.length ? V.describe(idx, { kind: "object", item: data.objects[0] }) : [];

// ---- the UI against a fake DOM ----
const calls = {};
const ctx = new Proxy({}, {
  get(t, k) {
    if (k in t) return t[k];
    return (...args) => { calls[k] = (calls[k] || 0) + 1; return args.length ? undefined : undefined; };
  },
  set(t, k, v) { t[k] = v; return true; },
});
function element(tag, id) {
  const e = {
    tagName: (tag || "div").toUpperCase(), id, text: "", className: "", style: {}, children: [],
    get textContent() { return this.text; },
    set textContent(v) { this.text = v; this.children = []; },  // as in a browser: the children go
    listeners: {}, checked: false, type: "", value: "",
    appendChild(c) { this.children.push(c); return c; },
    addEventListener(type, fn) { (this.listeners[type] = this.listeners[type] || []).push(fn); },
    classList: { add() {}, remove() {} },
    get firstElementChild() { return this.children[0]; },
    get lastElementChild() { return this.children[this.children.length - 1]; },
    clientWidth: 900, clientHeight: 700, width: 0, height: 0,
    getContext() { return ctx; },
  };
  return e;
}
const byId = {};
for (const id of ["title", "summary", "episode", "layers", "search", "matches", "info", "fit", "cursor", "band", "zmin", "zmax", "save"])
  byId[id] = element(id === "search" ? "input" : "div", id);
byId.view = element("canvas", "view");
byId.regions = element("div", "regions");
byId.regions.appendChild(element("ul"));
byId.scale = element("div", "scale");
byId.scale.appendChild(element("span"));
byId.scale.appendChild(element("div"));
byId["ussnav-data"] = element("script", "ussnav-data");
byId["ussnav-data"].textContent = dataText;
const windowListeners = {};
const document = {
  title: "",
  getElementById: (id) => byId[id] || null,
  createElement: (tag) => element(tag),
  createTextNode: (text) => ({ textContent: text }),
};
const window = { devicePixelRatio: 1, addEventListener(type, fn) { (windowListeners[type] = windowListeners[type] || []).push(fn); } };
vm.runInNewContext(code, { document, window, Math, JSON, Number, String, isFinite, Infinity, Map, console });

const fire = (list, ev) => { for (const fn of list || []) fn(ev); };
const drawsAtStart = calls.stroke || 0;
report.ui = { title: byId.title.textContent, summary: byId.summary.textContent, layers: byId.layers.children.length,
  regionItems: byId.regions.firstElementChild.children.length, episodeRows: byId.episode.children.length,
  strokesAtStart: drawsAtStart, fillRects: calls.fillRect || 0, scale: byId.scale.firstElementChild.textContent };
// Type a search.
byId.search.value = "bed";
fire(byId.search.listeners.input, { target: byId.search });
report.ui.matchesText = byId.matches.textContent;
// Click the first object's centre: screen position from the fitted view, read back from the
// cursor read-out of a mouse move at a known pixel.
fire(byId.view.listeners.mousemove, { offsetX: 0, offsetY: 0 });
const at0 = byId.cursor.textContent.match(/x (\S+)\s+y (\S+)/).map(Number);
fire(byId.view.listeners.mousemove, { offsetX: 100, offsetY: 100 });
const at1 = byId.cursor.textContent.match(/x (\S+)\s+y (\S+)/).map(Number);
const scale = 100 / (at1[1] - at0[1]);  // pixels per metre
report.ui.pxPerM = scale;
if (data.objects.length) {
  const o = data.objects[0];
  const px = (o.c[0] - at0[1]) * scale, py = (at0[2] - o.c[1]) * scale;
  fire(byId.view.listeners.mousedown, { offsetX: px, offsetY: py });
  fire(windowListeners.mouseup, { offsetX: px, offsetY: py, target: byId.view });
  report.ui.clickedInfo = byId.info.children.map((c) => c.textContent);
}
// The episode's coarse decisions: one item each; a click selects the region chosen.
const choices = byId.episode.children.find((c) => c.id === "choices");
report.ui.choices = choices ? choices.children.length : 0;
report.ui.choiceLines = choices ? choices.children.map((c) => c.textContent) : [];
if (choices && choices.children.length) {
  fire(choices.children[0].listeners.click, {});
  report.ui.choiceInfo = byId.info.children.map((c) => c.textContent);
}
// A height band above every node: the polyhedra are no longer drawn.
if (data.nodes.length) {
  report.ui.band = [byId.zmin.value, byId.zmax.value];
  const before = calls.fill || 0;
  byId.zmin.value = "1000"; byId.zmax.value = "1001";
  fire(byId.zmin.listeners.change);
  report.ui.fillsWithBand = (calls.fill || 0) - before;
  byId.zmin.value = String(report.ui.band[0]); byId.zmax.value = String(report.ui.band[1]);
  fire(byId.zmax.listeners.change);
  report.ui.fillsWithoutBand = (calls.fill || 0) - before - report.ui.fillsWithBand;
}
// Toggle every layer off and on again (each redraws).
for (const l of byId.layers.children) {
  const box = l.children[0];
  box.checked = !box.checked; fire(box.listeners.change);
  box.checked = !box.checked; fire(box.listeners.change);
}
report.ui.strokesAfter = calls.stroke || 0;
process.stdout.write(JSON.stringify(report));
