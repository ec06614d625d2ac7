// Runs the script of an eval index page (node index_check.js DIR/index.html) against a small fake
// DOM and prints a JSON report for test_eval_index.cpp: the summary rows, the episode rows as
// rendered, after a filter ("fail") and after a click on the SPL header.
"use strict";
const fs = require("fs");
const vm = require("vm");

const html = fs.readFileSync(process.argv[2], "utf8");
const open = '<script id="ussnav-data" type="application/json">';
const a = html.indexOf(open), b = html.indexOf("</script>", a);
const dataText = html.slice(a + open.length, b);
const c = html.indexOf("<script>", b), d = html.indexOf("</script>", c);
const code = html.slice(c + "<script>".length, d);

function element(tag) {
  return { tag, textContent: "", className: "", href: "", children: [], listeners: {},
    appendChild(x) { this.children.push(x); return x; },
    addEventListener(t, f) { (this.listeners[t] = this.listeners[t] || []).push(f); } };
}
const byId = {};
for (const id of ["title", "summary", "filter", "count", "episodes"]) byId[id] = element(id === "filter" ? "input" : "div");
byId["ussnav-data"] = element("script");
byId["ussnav-data"].textContent = dataText;
const table = byId.episodes;
// textContent = "" clears children, as in a browser
Object.defineProperty(table, "textContent", { get() { return ""; }, set() { this.children = []; } });
const document = { title: "", getElementById: (id) => byId[id], createElement: (t) => element(t),
  createTextNode: (t) => ({ textContent: t, children: [] }) };
vm.runInNewContext(code, { document, JSON, Number, String, Object, console, encodeURIComponent });

const text = (e) => (e.children.length ? e.children.map(text).join(" ").trim() : e.textContent);
const rows = () => table.children.slice(1).map((tr) => tr.children.map(text));
const links = () => table.children.slice(1).map((tr) => tr.children[tr.children.length - 1].children.filter((x) => x.tag === "a").map((x) => x.href));
const report = { title: byId.title.textContent, summary: byId.summary.children.length - 1,
  header: table.children[0].children.map((th) => th.textContent), rows: rows(), links: links(), count: byId.count.textContent };
byId.filter.listeners.input[0]({ target: { value: "fail" } });
report.failRows = rows();
byId.filter.listeners.input[0]({ target: { value: "" } });
table.children[0].children[6].listeners.click[0]();  // SPL
report.bySpl = rows().map((r) => r[6]);
process.stdout.write(JSON.stringify(report));
