// DIR/index.html of `ussnav eval` (see eval_index.hpp).

#include "ussnav/eval/eval_index.hpp"

#include <cctype>
#include <nlohmann/json.hpp>

#include "ussnav/core/io.hpp"

namespace ussnav {
namespace {

constexpr const char* kHead = R"ussnav_html(<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>ussnav eval</title>
<!-- Written by `ussnav eval` (src/eval/eval_index.cpp). Self-contained: the data is the JSON block below. -->
<style>
  body { font: 13px/1.4 system-ui, sans-serif; color: #222; margin: 16px; }
  h1 { font-size: 17px; } h2 { font-size: 14px; margin-top: 18px; }
  table { border-collapse: collapse; }
  th, td { padding: 2px 8px; border-bottom: 1px solid #e3e3e3; text-align: left; white-space: nowrap; }
  th { background: #f3f3f3; position: sticky; top: 0; }
  #episodes th { cursor: pointer; user-select: none; }
  td.num { text-align: right; font-variant-numeric: tabular-nums; }
  .ok { color: #1a7f37; } .fail { color: #c62828; font-weight: 600; }
  .muted { color: #777; }
  input { padding: 4px; width: 320px; }
</style>
</head>
<body>
<h1 id="title"></h1>
<h2>Summary</h2>
<table id="summary"></table>
<p class="muted">SR: success rate; SPL = S &middot; L* / max(L, L*); single_room: a goal instance is in the start room;
  long_horizon: multi_room with L* &ge; 15 m (docs/eval.md).</p>
<h2>Episodes</h2>
<p><input id="filter" type="search" placeholder="filter: any text of a row, e.g. office or toilet or fail">
  <span id="count" class="muted"></span></p>
<table id="episodes"></table>
<script id="ussnav-data" type="application/json">)ussnav_html";

constexpr const char* kTail = R"ussnav_html(</script>
<script>
"use strict";
(() => {
  const data = JSON.parse(document.getElementById("ussnav-data").textContent);
  const el = (tag, text, cls) => { const e = document.createElement(tag); if (text !== undefined) e.textContent = text; if (cls) e.className = cls; return e; };
  document.getElementById("title").textContent = data.title;
  document.title = data.title;
  const fx = (x, d) => (x === null || x === undefined || x < 0 ? "-" : Number(x).toFixed(d));

  // Summary: planner x split.
  const sum = document.getElementById("summary"), splits = ["single_room", "multi_room", "long_horizon", "all"];
  const hr = el("tr");
  for (const h of ["planner", "split", "episodes", "SR", "SPL", "path m", "time s"]) hr.appendChild(el("th", h));
  sum.appendChild(hr);
  for (const [planner, by] of Object.entries(data.summary)) {
    for (const s of splits) {
      const v = by[s];
      if (!v || !v.episodes) continue;
      const tr = el("tr");
      tr.appendChild(el("td", planner)); tr.appendChild(el("td", s));
      tr.appendChild(el("td", String(v.episodes), "num")); tr.appendChild(el("td", fx(v.sr, 3), "num"));
      tr.appendChild(el("td", fx(v.spl, 3), "num")); tr.appendChild(el("td", fx(v.path_length_m, 1), "num"));
      tr.appendChild(el("td", fx(v.time_s, 1), "num"));
      sum.appendChild(tr);
    }
  }

  // Episodes: sortable, filterable.
  const cols = [
    ["world", (r) => r.world], ["goal", (r) => r.goal], ["planner", (r) => r.planner], ["seed", (r) => r.seed],
    ["split", (r) => r.split], ["result", (r) => (r.success ? "found " + r.found : r.end_reason)],
    ["SPL", (r) => r.spl, 3], ["path m", (r) => r.path, 1], ["L* m", (r) => r.lstar, 1], ["time s", (r) => r.time, 1],
    ["labels", (r) => (r.labels_scored ? r.labels_correct / r.labels_scored : -1)], ["files", (r) => r.folder || ""],
  ];
  let sortCol = -1, sortDir = 1, filter = "";
  const table = document.getElementById("episodes");
  function render() {
    table.textContent = "";
    const hr = el("tr");
    cols.forEach(([name], i) => {
      const th = el("th", name + (i === sortCol ? (sortDir > 0 ? " \u25b2" : " \u25bc") : ""));
      th.addEventListener("click", () => { sortDir = i === sortCol ? -sortDir : 1; sortCol = i; render(); });
      hr.appendChild(th);
    });
    table.appendChild(hr);
    let rows = data.rows.filter((r) => !filter || (JSON.stringify(r) + (r.success ? " found" : " fail")).toLowerCase().includes(filter));
    if (sortCol >= 0) {
      const key = cols[sortCol][1];
      rows = rows.slice().sort((a, b) => { const x = key(a), y = key(b); return (x < y ? -1 : x > y ? 1 : 0) * sortDir; });
    }
    for (const r of rows) {
      const tr = el("tr");
      cols.forEach(([name, key, digits]) => {
        const v = key(r);
        let td;
        if (name === "result") td = el("td", v, r.success ? "ok" : "fail");
        else if (name === "labels") td = el("td", r.labels_scored ? r.labels_correct + "/" + r.labels_scored : "-", "num");
        else if (name === "files") {
          td = el("td");
          if (r.folder) for (const [f, t] of [["scene_graph.html", "graph"], ["topdown.png", "picture"], ["result.json", "result"]]) {
            const a = el("a", t); a.href = "episodes/" + encodeURIComponent(r.folder) + "/" + f; td.appendChild(a); td.appendChild(document.createTextNode(" "));
          }
        } else td = el("td", digits !== undefined ? fx(v, digits) : String(v), digits !== undefined ? "num" : "");
        tr.appendChild(td);
      });
      table.appendChild(tr);
    }
    document.getElementById("count").textContent = rows.length + " of " + data.rows.length + " episodes";
  }
  document.getElementById("filter").addEventListener("input", (e) => { filter = e.target.value.trim().toLowerCase(); render(); });
  render();
})();
</script>
</body>
</html>
)ussnav_html";

}  // namespace

std::string episodeFolderName(const EpisodeRow& r) {
  std::string goal = r.goal;
  for (char& c : goal)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
  return r.world + "_" + goal + "_" + r.planner + "_s" + std::to_string(r.seed);
}

std::string evalIndexHtml(const std::vector<EpisodeRow>& rows, const std::vector<bool>& saved, const std::string& title) {
  nlohmann::json d;
  d["title"] = title;
  d["summary"] = summaryJson(rows);
  nlohmann::json list = nlohmann::json::array();
  for (size_t i = 0; i < rows.size(); ++i) {
    const EpisodeRow& r = rows[i];
    list.push_back({{"world", r.world}, {"goal", r.goal}, {"planner", r.planner}, {"seed", r.seed}, {"split", r.split},
                    {"success", r.success}, {"found", r.found_label}, {"end_reason", r.end_reason}, {"spl", r.spl},
                    {"path", r.path_length_m}, {"lstar", r.shortest_path_m}, {"time", r.time_s},
                    {"labels_scored", r.labels_scored}, {"labels_correct", r.labels_correct},
                    {"folder", i < saved.size() && saved[i] ? nlohmann::json(episodeFolderName(r)) : nlohmann::json(nullptr)}});
  }
  d["rows"] = std::move(list);
  return std::string(kHead) + jsonForScript(d) + kTail;
}

}  // namespace ussnav
