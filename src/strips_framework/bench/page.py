"""``report.html``: the benchmark report as a page, in the shape Downward Lab users read.

Coverage and score tables per domain (one row per domain, one column per
configuration, the best of a row in bold, a sum row at the bottom), a sortable and
filterable per-task table, the cactus plot, and a scatter plot whose two configurations
and measure are picked on the page, each point named on hover. The page is one file
(data, script and style inline) beside the plots it links; it needs no network.

Scores are Lab's: a solved task's expansions score 1 at 100 or fewer and 0 at a
million, its time score 1 at a second or less and 0 at the time limit, logarithmic in
between; an unsolved task scores 0. :func:`lab_properties` gives the results as a Lab
``properties`` file, so Lab's reports can load them.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from html import escape
from typing import Any

from strips_framework.bench.summary import COLUMNS, Task, configs, summary_rows

#: (low, high) bounds of Lab's log scores: the value scoring 1, the value scoring 0.
EXPANSION_BOUNDS = (100.0, 1e6)
TIME_LOW = 1.0
#: Lab's ``error`` attribute for each status of ours.
LAB_ERRORS = {"solved": "success", "timeout": "search-out-of-time",
              "memout": "search-out-of-memory", "unsolved": "search-unsolvable-incomplete",
              "crash": "search-critical-error", "invalid": "search-plan-invalid"}


def log_score(value: float | None, low: float, high: float) -> float:
    """1 for ``value <= low``, 0 for ``value >= high`` or no value, logarithmic between
    (rounded to two places, as Lab does)."""
    if value is None:
        return 0.0
    value = min(max(value, low), high)
    return round(math.log(high / value) / math.log(high / low), 2) if high > low else 1.0


def scores(task: Task, time_limit: float) -> dict[str, float]:
    """The task's ``score_expansions`` and ``score_total_time`` (0 unless solved)."""
    if not task.solved:
        return {"score_expansions": 0.0, "score_total_time": 0.0}
    return {
        "score_expansions": log_score(task.expanded, *EXPANSION_BOUNDS),
        "score_total_time": log_score(task.time, TIME_LOW, max(time_limit, TIME_LOW * 1.01)),
    }


def lab_properties(found: Sequence[Task], time_limit: float) -> dict[str, dict[str, Any]]:
    """The results as Downward Lab's ``properties``: one entry per run id
    ``algorithm-domain-problem``, with Lab's attribute names."""
    properties = {}
    for task in found:
        problem = task.problem.rsplit("/", 1)[-1]
        entry = {
            "id": [task.config, task.domain, problem],
            "algorithm": task.config,
            "domain": task.domain,
            "problem": problem,
            "coverage": int(task.solved),
            "error": LAB_ERRORS.get(task.status, task.status),
            "total_time": task.time,
            "planner_time": task.planner_seconds,
            "expansions": task.expanded if task.solved else None,
            "plan_length": task.plan_length if task.solved else None,
            "cost": task.plan_length if task.solved else None,
        } | scores(task, time_limit)
        properties[f"{task.config}-{task.domain}-{problem}"] = entry
    return properties


def _domain_table(found: Sequence[Task], names: list[str], value: Any, digits: int) -> str:
    """Rows per domain, a column per configuration, ``value(task)`` summed; the best
    (highest) of each row in bold, and a sum row."""
    domains = sorted({task.domain for task in found})
    totals = dict.fromkeys(names, 0.0)
    rows = []
    for domain in [*domains, None]:
        if domain is None:
            sums, label = totals, "Sum"
        else:
            mine = [t for t in found if t.domain == domain]
            count = len({t.problem for t in mine})
            sums = {name: sum(value(t) for t in mine if t.config == name) for name in names}
            for name in names:
                totals[name] += sums[name]
            label = f"{domain} ({count})"
        best = max(sums.values(), default=0)
        cells = "".join(
            f"<td{' class=best' if sums[n] == best and best > 0 else ''}>{sums[n]:.{digits}f}</td>"
            for n in names
        )
        rows.append(f"<tr{' class=sum' if domain is None else ''}><th>{escape(label)}</th>{cells}</tr>")
    head = "".join(f"<th>{escape(n)}</th>" for n in names)
    return f"<table class='domains'><tr><th>domain (problems)</th>{head}</tr>{''.join(rows)}</table>"


def report_page(found: Sequence[Task], title: str, intro: str, time_limit: float,
                images: Sequence[str]) -> str:
    """The page (see the module docstring); ``images`` are the plot files beside it."""
    names = configs(found)
    summary = "".join(
        "<tr>" + "".join(f"<td>{escape(cell)}</td>" for cell in row) + "</tr>"
        for row in summary_rows(found)
    )
    tasks = [
        {"domain": t.domain, "problem": t.problem, "config": t.config, "status": t.status,
         "solved": t.solved, "time": t.time, "planner": t.planner_seconds,
         "expanded": t.expanded, "length": t.plan_length} | scores(t, time_limit)
        for t in found
    ]
    data = json.dumps({"configs": names, "tasks": tasks, "limit": time_limit},
                      allow_nan=False).replace("</", "<\\/")
    pictures = "".join(f'<figure><img src="{escape(name)}" alt="{escape(name)}"></figure>'
                       for name in images)
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{escape(title)}</title>
<style>{_STYLE}</style></head><body>
<h1>{escape(title)}</h1>
<p>{escape(intro)}</p>
<h2>Summary</h2>
<table class="summary"><tr>{''.join(f'<th>{escape(c)}</th>' for c in COLUMNS)}</tr>{summary}</table>
<h2>Coverage per domain</h2>
{_domain_table(found, names, lambda t: int(t.solved), 0)}
<h2>Expansions score per domain</h2>
<p class="note">Lab's score_expansions: 1 for 100 expansions or fewer, 0 for a million or
unsolved, logarithmic between; summed over the domain's problems.</p>
{_domain_table(found, names, lambda t: scores(t, time_limit)["score_expansions"], 2)}
<h2>Time score per domain</h2>
<p class="note">Lab's score_total_time: 1 for a second or less, 0 at the time limit
({time_limit:g} s) or unsolved, logarithmic between.</p>
{_domain_table(found, names, lambda t: scores(t, time_limit)["score_total_time"], 2)}
<h2>Coverage over time</h2>
{pictures}
<h2>Scatter</h2>
<p>x <select id="sx"></select> y <select id="sy"></select> measure
<select id="sm"><option value="time">wall-clock time (s)</option>
<option value="expanded">expansions</option><option value="length">plan length</option></select>
<span id="scatter-note"></span></p>
<div id="scatter"></div>
<h2>Per task</h2>
<p><input id="filter" type="search" placeholder="filter: domain, problem, configuration, status"
 size="50"> <span id="row-count"></span> (click a column's header to sort)</p>
<table id="tasks"><thead><tr></tr></thead><tbody></tbody></table>
<script type="application/json" id="data">{data}</script>
<script>{_SCRIPT}</script>
</body></html>
"""


_STYLE = """
body { font: 14px/1.4 system-ui, sans-serif; margin: 16px; color: #111; }
table { border-collapse: collapse; margin: 6px 0 14px; font-size: 13px; }
th, td { border: 1px solid #bbb; padding: 2px 7px; text-align: right; }
th { background: #f2f4f4; } td:first-child, th:first-child { text-align: left; white-space: nowrap; }
td.best { font-weight: bold; background: #e9f7ef; } tr.sum th, tr.sum td { border-top: 2px solid #555; }
#tasks th { cursor: pointer; position: sticky; top: 0; }
#tasks td.unsolved { color: #a93226; }
figure { margin: 0; } img { max-width: 100%; }
.note { color: #555; font-size: 12px; }
#scatter svg circle:hover { stroke: #000; stroke-width: 2; }
"""

_SCRIPT = r"""
(function () {
  const data = JSON.parse(document.getElementById("data").textContent);
  const $ = (id) => document.getElementById(id);
  // The per-task table: sortable by any column, filtered by a text.
  const columns = [["domain", "domain"], ["problem", "problem"], ["config", "configuration"],
    ["status", "status"], ["time", "wall time (s)"], ["planner", "planner time (s)"],
    ["expanded", "expansions"], ["length", "plan length"],
    ["score_expansions", "score expansions"], ["score_total_time", "score time"]];
  let sortKey = null, ascending = true;
  const head = document.querySelector("#tasks thead tr");
  columns.forEach(([key, name]) => {
    const th = document.createElement("th");
    th.textContent = name; th.dataset.key = key;
    th.addEventListener("click", () => { ascending = sortKey === key ? !ascending : true; sortKey = key; rows(); });
    head.append(th);
  });
  const show = (v) => v === null || v === undefined ? "-" : typeof v === "number" ? String(+v.toFixed(4)) : String(v);
  function rows() {
    const words = $("filter").value.toLowerCase().split(/\s+/).filter(Boolean);
    let shown = data.tasks.filter((t) => {
      const text = [t.domain, t.problem, t.config, t.status].join(" ").toLowerCase();
      return words.every((w) => text.includes(w));
    });
    if (sortKey) {
      shown = shown.slice().sort((a, b) => {
        const x = a[sortKey], y = b[sortKey];
        if (x === y) return 0;
        if (x === null || x === undefined) return 1;
        if (y === null || y === undefined) return -1;
        const order = typeof x === "number" ? x - y : String(x).localeCompare(String(y));
        return ascending ? order : -order;
      });
    }
    const body = document.querySelector("#tasks tbody");
    body.replaceChildren(...shown.map((t) => {
      const tr = document.createElement("tr");
      columns.forEach(([key]) => {
        const td = document.createElement("td");
        td.textContent = show(t[key]);
        if (key === "status" && !t.solved) td.className = "unsolved";
        tr.append(td);
      });
      return tr;
    }));
    $("row-count").textContent = shown.length + " of " + data.tasks.length + " tasks";
  }
  $("filter").addEventListener("input", rows);
  rows();
  // The scatter plot: one point per problem, named on hover.
  const sx = $("sx"), sy = $("sy");
  data.configs.forEach((c, i) => {
    sx.add(new Option(c, c, false, i === 0));
    sy.add(new Option(c, c, false, i === Math.min(1, data.configs.length - 1)));
  });
  function scatter() {
    const metric = $("sm").value, a = sx.value, b = sy.value;
    const by = new Map(data.tasks.map((t) => [t.config + "\u0000" + t.problem, t]));
    const problems = [...new Set(data.tasks.map((t) => t.problem))];
    const value = (t) => t && t.solved && t[metric] !== null && t[metric] > 0 ? t[metric] : null;
    const pairs = problems.map((p) => [p, value(by.get(a + "\u0000" + p)), value(by.get(b + "\u0000" + p))]);
    const measured = pairs.flatMap(([, x, y]) => [x, y]).filter((v) => v !== null);
    const top = Math.max(...measured, metric === "time" ? data.limit : 1) * 2;
    const low = Math.max(Math.min(...measured, top / 10) / 2, 1e-6);
    const W = 460, P = 48, L = Math.log(low), H = Math.log(top);
    const pos = (v) => P + (W - P - 10) * (Math.log(v) - L) / (H - L);
    const ypos = (v) => W - P - (W - P - 10) * (Math.log(v) - L) / (H - L);
    let svg = '<svg xmlns="http://www.w3.org/2000/svg" width="' + W + '" height="' + W + '" font-size="11">';
    svg += '<rect x="' + P + '" y="10" width="' + (W - P - 10) + '" height="' + (W - P - 10) + '" fill="none" stroke="#333"/>';
    svg += '<line x1="' + pos(low) + '" y1="' + ypos(low) + '" x2="' + pos(top) + '" y2="' + ypos(top) + '" stroke="#aaa"/>';
    for (let e = Math.ceil(Math.log10(low)); e <= Math.log10(top); e++) {
      const v = Math.pow(10, e);
      svg += '<text x="' + pos(v) + '" y="' + (W - P + 14) + '" text-anchor="middle">' + v + '</text>';
      svg += '<text x="' + (P - 4) + '" y="' + (ypos(v) + 4) + '" text-anchor="end">' + v + '</text>';
    }
    svg += '<text x="' + (W / 2) + '" y="' + (W - 8) + '" text-anchor="middle">' + a + '</text>';
    svg += '<text x="12" y="' + (W / 2) + '" transform="rotate(-90 12 ' + (W / 2) + ')" text-anchor="middle">' + b + '</text>';
    let both = 0, one = 0;
    const esc = (s) => String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;");
    pairs.forEach(([p, x, y]) => {
      if (x === null && y === null) return;
      const unsolved = x === null || y === null;
      if (unsolved) one++; else both++;
      const px = pos(x === null ? top : x), py = ypos(y === null ? top : y);
      svg += '<circle class="point" cx="' + px + '" cy="' + py + '" r="4" fill="' + (unsolved ? "#c0392b" : "#2471a3")
        + '" fill-opacity="0.75"><title>' + esc(p) + ": " + esc(a) + " " + show(x) + ", " + esc(b) + " " + show(y) + '</title></circle>';
    });
    svg += "</svg>";
    $("scatter").innerHTML = svg;
    $("scatter-note").textContent = both + " problems solved by both, " + one + " by one only (red, on the unsolved edge)";
  }
  [sx, sy, $("sm")].forEach((s) => s.addEventListener("change", scatter));
  scatter();
})();
"""
