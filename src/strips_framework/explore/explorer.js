// The search explorer: draws the search tree of the JSON document in #data on a canvas
// (thousands of nodes: only the visible ones are drawn), and shows the clicked node's
// details in the side panel. No network, no libraries: the page works from file://.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("data").textContent);
  const S = data.strings;
  const nodes = data.nodes;
  const byId = new Map();
  nodes.forEach((n, i) => { n.index = i; n.kids = []; byId.set(n.id, n); });
  const roots = [];
  nodes.forEach((n) => {
    const p = n.parent === null || n.parent === undefined ? null : byId.get(n.parent);
    n.up = p || null;
    if (p) p.kids.push(n); else roots.push(n);
  });
  const forward = data.kind === "forward";
  const $ = (id) => document.getElementById(id);
  const el = (tag, attrs, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === "class") e.className = v; else if (k === "text") e.textContent = v; else e.setAttribute(k, v);
    }
    children.forEach((c) => e.append(c));
    return e;
  };

  // Layout: leaves side by side in depth-first order, a parent centred over its children.
    let slot = 0, maxDepth = 0;
  for (const root of roots) {
    const stack = [[root, 0, false]];
    while (stack.length) {
      const [n, depth, done] = stack.pop();
      if (done) {
        n.x = n.kids.length ? (n.kids[0].x + n.kids[n.kids.length - 1].x) / 2 : slot++;
        continue;
      }
      n.depth = depth; n.y = depth; if (depth > maxDepth) maxDepth = depth;
      stack.push([n, depth, true]);
      for (let k = n.kids.length - 1; k >= 0; k--) stack.push([n.kids[k], depth + 1, false]);
    }
    slot += 1;  // a gap between the trees of several roots
  }
  const modelName = (n) => (forward ? "s" + n.id : "M" + n.model);
  // A field named "level" (ABSTRIPS) joins the label; any other shows in the panel.
  const label = (n) => (forward ? "s" + n.id + (n.h === "-" || n.h === null ? "" : " h=" + n.h)
    : "n" + n.id + " " + modelName(n) + (n.extra && n.extra.level !== undefined ? " L" + n.extra.level : ""));

  // View: world coordinates (x in slots, y in levels) to canvas pixels.
  const canvas = $("tree");
  const ctx = canvas.getContext("2d");
  // sx: pixels between neighbouring leaves; sy: pixels between levels.
  const view = { sx: 80, sy: 50, ox: 40, oy: 30 };
  let selected = null, matches = new Set();
  const toScreen = (x, y) => [view.ox + x * view.sx, view.oy + y * view.sy];
  const toWorld = (px, py) => [(px - view.ox) / view.sx, (py - view.oy) / view.sy];
  const boxSize = () => [Math.min(view.sx * 0.9, 110), Math.min(view.sy * 0.6, 22)];
  const detailed = () => view.sx >= 48 && view.sy >= 26;

  function resize() {
    const box = canvas.parentElement.getBoundingClientRect();
    const ratio = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, box.width * ratio); canvas.height = Math.max(1, box.height * ratio);
    canvas.style.width = box.width + "px"; canvas.style.height = box.height + "px";
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    draw();
  }
  function fit() {
    const box = canvas.parentElement.getBoundingClientRect();
    view.sx = Math.max(0.05, Math.min(100, (box.width - 60) / Math.max(slot - 1, 1)));
    view.sy = Math.max(2, Math.min(56, (box.height - 50) / Math.max(maxDepth, 1)));
    view.ox = 30 + Math.min(view.sx * 0.45, 55); view.oy = 25;
    draw();
  }
  function draw() {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    ctx.clearRect(0, 0, w, h);
    const [x0, y0] = toWorld(-50, -50), [x1, y1] = toWorld(w + 50, h + 50);
    const visible = (n) => n.x >= x0 && n.x <= x1 && n.y >= y0 && n.y <= y1;
    const full = detailed();
    // Edges and dots are batched into one path per style: one stroke for thousands.
    const batches = new Map();
    const batch = (key) => { let p = batches.get(key); if (!p) { p = new Path2D(); batches.set(key, p); } return p; };
    for (const n of nodes) {
      if (!n.up) continue;
      if (!visible(n) && !visible(n.up)) continue;
      const [ax, ay] = toScreen(n.up.x, n.up.y), [bx, by] = toScreen(n.x, n.y);
      const applied = n.applied !== undefined && n.applied !== null;  // world models: not a subgoal
      const style = n.path && n.up.path ? "#c0392b|2.5" : applied ? "#555|1.5" : forward ? "#555|1" : "#aaa|1";
      const path = batch(style);
      path.moveTo(ax, ay); path.lineTo(bx, by);
    }
    for (const [style, path] of batches) {
      const [colour, width] = style.split("|");
      ctx.strokeStyle = colour; ctx.lineWidth = +width; ctx.stroke(path);
    }
    ctx.font = "11px sans-serif"; ctx.textAlign = "center"; ctx.textBaseline = "middle";
    const [bw, bh] = boxSize();
    const r = Math.max(2, Math.min(bw, bh, 12) / 2);
    const dots = new Map();
    for (const n of nodes) {
      if (!visible(n)) continue;
      const [sx, sy] = toScreen(n.x, n.y);
      let fill = "#ffffff";
      if (!forward && n.diff === null) fill = "#d5f5e3";
      if (forward && n.h === null) fill = "#d7ccc8";
      if (matches.has(n)) fill = "#f9e79f";
      const stroke = n === selected ? "#1f618d" : n.macrop ? "#7d3c98" : n.path ? "#c0392b" : "#777";
      const width = n === selected ? 3 : n.path || n.macrop ? 2.5 : 1;
      if (full) {
        ctx.fillStyle = fill; ctx.strokeStyle = stroke; ctx.lineWidth = width;
        ctx.fillRect(sx - bw / 2, sy - bh / 2, bw, bh); ctx.strokeRect(sx - bw / 2, sy - bh / 2, bw, bh);
        ctx.fillStyle = "#111"; ctx.fillText(label(n), sx, sy, bw - 4);
      } else {
        const key = fill + "|" + stroke + "|" + width;
        let path = dots.get(key);
        if (!path) { path = new Path2D(); dots.set(key, path); }
        const radius = n === selected ? r + 2 : r;
        path.moveTo(sx + radius, sy); path.arc(sx, sy, radius, 0, 2 * Math.PI);
      }
    }
    for (const [key, path] of dots) {
      const [fill, stroke, width] = key.split("|");
      ctx.fillStyle = fill; ctx.strokeStyle = stroke; ctx.lineWidth = +width;
      ctx.fill(path); ctx.stroke(path);
    }
  }
  function nodeAt(px, py) {
    const [wx, wy] = toWorld(px, py);
    let best = null, bestD = Infinity;
    const [bw, bh] = boxSize();
    const limitX = Math.max(bw / 2, 6) / view.sx, limitY = Math.max(bh / 2, 6) / view.sy;
    for (const n of nodes) {
      const dx = Math.abs(n.x - wx) / limitX, dy = Math.abs(n.y - wy) / limitY;
      if (dx <= 1 && dy <= 1) {
        const d = dx + dy;
        if (d < bestD) { best = n; bestD = d; }
      }
    }
    return best;
  }
  function centre(n) {
    const box = canvas.getBoundingClientRect();
    if (!detailed()) { view.sx = Math.max(view.sx, 80); view.sy = Math.max(view.sy, 50); }
    view.ox = box.width / 2 - n.x * view.sx; view.oy = box.height / 3 - n.y * view.sy;
  }

  // Interaction: drag to pan, wheel to zoom, click to select, arrows to walk the tree.
  let drag = null;
  canvas.addEventListener("mousedown", (e) => { drag = { x: e.clientX, y: e.clientY, ox: view.ox, oy: view.oy, moved: false }; });
  window.addEventListener("mousemove", (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) > 3) drag.moved = true;
    view.ox = drag.ox + dx; view.oy = drag.oy + dy; draw();
  });
  window.addEventListener("mouseup", (e) => {
    if (drag && !drag.moved) {
      const box = canvas.getBoundingClientRect();
      const n = nodeAt(e.clientX - box.left, e.clientY - box.top);
      if (n) select(n, false);
    }
    drag = null;
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    const box = canvas.getBoundingClientRect();
    const px = e.clientX - box.left, py = e.clientY - box.top;
    const [wx, wy] = toWorld(px, py);
    zoom(e.deltaY < 0 ? 1.2 : 1 / 1.2, px, py, wx, wy);
    draw();
  }, { passive: false });
  window.addEventListener("keydown", (e) => {
    if (!selected || e.target.tagName === "INPUT") return;
    const siblings = selected.up ? selected.up.kids : roots;
    const at = siblings.indexOf(selected);
    const next = { ArrowUp: selected.up, ArrowDown: selected.kids[0],
      ArrowLeft: siblings[at - 1], ArrowRight: siblings[at + 1] }[e.key];
    if (next) { e.preventDefault(); select(next, true); }
  });
  $("fit").addEventListener("click", fit);
  function zoom(factor, px, py, wx, wy) {
    if (px === undefined) {
      const box = canvas.getBoundingClientRect();
      px = box.width / 2; py = box.height / 2; [wx, wy] = toWorld(px, py);
    }
    view.sx = Math.max(0.02, Math.min(400, view.sx * factor));
    view.sy = Math.max(1, Math.min(200, view.sy * factor));
    view.ox = px - wx * view.sx; view.oy = py - wy * view.sy;
    draw();
  }
  $("zoom-in").addEventListener("click", () => zoom(1.5));
  $("zoom-out").addEventListener("click", () => zoom(1 / 1.5));
  const goal = nodes.find((n) => n.path && !n.kids.some((k) => k.path)) || null;
  $("goal").addEventListener("click", () => { if (goal) select(goal, true); });
  $("goal").disabled = !goal;

  // Search: every node's text (goals, operators, model changes, fields) holds the words.
  let texts = null;
  function nodeText(n) {
    const parts = [label(n)];
    if (forward) {
      if (n.op !== null) parts.push(S[n.op]);
      n.add.concat(n.del).forEach((i) => parts.push(S[i]));
    } else {
      n.goals.forEach(([f, o]) => { parts.push(S[f]); if (o !== null) parts.push(S[o]); });
      if (n.applied !== null) parts.push(S[n.applied]);
      const m = data.models[n.model];
      m.add.concat(m.del).forEach((i) => parts.push(S[i]));
      Object.entries(n.extra || {}).forEach(([k, v]) => parts.push(k + "=" + v));
    }
    return parts.join("\n").toLowerCase();
  }
  $("search").addEventListener("input", () => {
    const q = $("search").value.trim().toLowerCase();
    const list = $("matches");
    list.replaceChildren();
    matches = new Set();
    if (q) {
      if (!texts) texts = nodes.map(nodeText);
      nodes.forEach((n, i) => { if (texts[i].includes(q)) matches.add(n); });
      $("match-count").textContent = matches.size + " nodes match";
      let shown = 0;
      for (const n of matches) {
        if (shown++ >= 200) break;
        const item = el("li", { text: label(n) + (n.path ? " (solution path)" : "") });
        item.addEventListener("click", () => select(n, true));
        list.append(item);
      }
    } else {
      $("match-count").textContent = "";
    }
    draw();
  });

  // The details of one node.
  function section(title, ...content) {
    return el("section", {}, el("h3", { text: title }), ...content);
  }
  function list(items, id, cls) {
    const ul = el("ul", id ? { id: id } : {});
    if (!items.length) ul.append(el("li", { class: "none", text: "none" }));
    items.forEach((t) => ul.append(el("li", cls ? { class: cls } : {}, t)));
    return ul;
  }
  function scoreTable(scores) {
    const table = el("table", { id: "detail-scores" });
    const names = [];
    scores.forEach(([, parts]) => Object.keys(parts || {}).forEach((k) => { if (!names.includes(k)) names.push(k); }));
    table.append(el("tr", {}, el("th", { text: "#" }), el("th", { text: "score" }), ...names.map((k) => el("th", { text: k }))));
    scores.forEach(([score, parts], i) => {
      table.append(el("tr", {}, el("td", { text: String(i + 1) }), el("td", { text: score === null ? "∞" : String(+score.toFixed(3)) }),
        ...names.map((k) => el("td", { text: parts && k in parts ? String(+Number(parts[k]).toFixed(3)) : "" }))));
    });
    return table;
  }
  function worldModelDetails(n) {
    const out = [];
    const how = n.up === null ? "the root: M0 and the task's goal G0"
      : n.applied !== null ? "applying " + S[n.applied] + " (its precondition was proved)"
        : "a subgoal: the precondition of " + S[n.goals[0][1]] + ", relevant to the parent's difference";
    out.push(el("p", { id: "detail-how", text: how }));
    if (n.macrop) out.push(section("MACROP used", list(n.macrop.map((i) => S[i]), "detail-macrop")));
    const goals = el("ol", { id: "detail-goals" });
    n.goals.forEach(([f, o], i) => {
      const who = o === null ? "G0" : "pre " + S[o];
      goals.append(el("li", { class: i === 0 ? "first" : "" }, el("b", { text: who + ": " }), el("code", { text: S[f] })));
    });
    out.push(section("Goal list (first goal on top)", goals));
    const m = data.models[n.model];
    out.push(section("World model M" + n.model + " = M0 + additions − deletions",
      el("h4", { text: "ADDITIONS" }), list(m.add.map((i) => el("code", { text: S[i] })), "detail-add", "add"),
      el("h4", { text: "DELETIONS" }), list(m.del.map((i) => el("code", { text: S[i] })), "detail-del", "del")));
    if (n.scores) out.push(section("Evaluator's scores (lower is expanded first)", scoreTable(n.scores)));
    else out.push(section("Evaluator's scores", el("p", { class: "none", text: "not scored: the node was never queued (its first goal was proved, or nothing relevant was left)" })));
    const diff = n.diff === null ? null : data.differences[n.diff];
    out.push(section("Difference (the uncompleted proof of the first goal)",
      diff === null ? el("p", { id: "detail-diff", text: "none: the first goal was proved" })
        : list(diff.map((i) => el("code", { text: S[i] })), "detail-diff")));
    if (n.relevant) {
      out.push(section("Relevant operator instances (when first queued)",
        list(n.relevant.map(([o, r]) => el("span", {}, el("code", { text: S[o] }),
          S[r] === "false" ? " completes that proof (empty resolvent)" : " leaves ", S[r] === "false" ? "" : el("code", { text: S[r] }))), "detail-relevant")));
    }
    return out;
  }
  function forwardDetails(n) {
    const out = [];
    out.push(el("p", { id: "detail-how", text: n.up === null && n.op === null ? "the initial state" : "reached by " + (n.op === null ? "?" : S[n.op]) }));
    out.push(section("Path cost and estimate", el("table", { id: "detail-scores" },
      el("tr", {}, el("th", { text: "g" }), el("th", { text: "h" }), el("th", { text: "successors reached" })),
      el("tr", {}, el("td", { text: String(n.g) }), el("td", { text: n.h === null ? "∞ (dead end)" : String(n.h) }), el("td", { text: String(n.children) })))));
    out.push(section("State = initial state + added − deleted facts",
      el("h4", { text: "ADDED" }), list(n.add.map((i) => el("code", { text: S[i] })), "detail-add", "add"),
      el("h4", { text: "DELETED" }), list(n.del.map((i) => el("code", { text: S[i] })), "detail-del", "del")));
    return out;
  }
  function select(n, move) {
    selected = n;
    if (move) centre(n);
    const panel = $("detail");
    const head = el("h2", { id: "detail-title", text: label(n) + " · depth " + n.depth + (n.path ? " · on the solution path" : "") });
    const body = forward ? forwardDetails(n) : worldModelDetails(n);
    if (n.extra) {
      const dl = el("dl", { id: "detail-extra" });
      Object.entries(n.extra).forEach(([k, v]) => dl.append(el("dt", { text: k }), el("dd", { text: v })));
      body.push(section("Other fields", dl));
    }
    panel.replaceChildren(head, ...body);
    panel.scrollTop = 0;
    draw();
  }

  // The best h over expansions (forward search).
  function curve() {
    if (!forward || !data.curve.length) return;
    const points = data.curve.filter((p) => p[2] !== null);
    if (!points.length) return;
    const W = 320, H = 150, L = 36, B = 26;
    const maxE = Math.max(1, data.expansions, ...points.map((p) => p[0]));
    const maxH = Math.max(1, ...points.map((p) => p[2]));
    const X = (e) => L + (W - L - 8) * e / maxE, Y = (h) => H - B - (H - B - 8) * h / maxH;
    let d = "M" + X(points[0][0]) + "," + Y(points[0][2]);
    for (let i = 1; i < points.length; i++) d += " H" + X(points[i][0]) + " V" + Y(points[i][2]);
    d += " H" + X(maxE);
    const svg = '<svg id="curve-svg" width="' + W + '" height="' + H + '" xmlns="http://www.w3.org/2000/svg" font-size="10">'
      + '<line x1="' + L + '" y1="' + (H - B) + '" x2="' + (W - 8) + '" y2="' + (H - B) + '" stroke="#333"/>'
      + '<line x1="' + L + '" y1="8" x2="' + L + '" y2="' + (H - B) + '" stroke="#333"/>'
      + '<path d="' + d + '" fill="none" stroke="#c0392b" stroke-width="2"/>'
      + '<text x="' + L + '" y="' + (H - 12) + '">0</text><text x="' + (W - 8) + '" y="' + (H - 12) + '" text-anchor="end">' + maxE + ' expansions</text>'
      + '<text x="' + (L - 4) + '" y="' + (Y(maxH) + 4) + '" text-anchor="end">' + maxH + '</text><text x="' + (L - 4) + '" y="' + (H - B) + '" text-anchor="end">0</text>'
      + '<text x="4" y="' + (H / 2) + '" transform="rotate(-90 10 ' + (H / 2) + ')">best h</text></svg>';
    $("curve").innerHTML = "<h3>Best h over expansions</h3>" + svg;
  }

  // The summary line.
  const stats = Object.entries(data.statistics).map(([k, v]) => k + " " + v).join(", ");
  $("summary").textContent = data.title + ": " + data.status + (data.plan.length ? ", plan of " + data.plan.length + " steps" : "")
    + " · " + nodes.length + (forward ? " states shown of " + data.reached + " reached" : " nodes") + " · " + stats;
  if (data.plan.length) {
    const plan = el("ol", { id: "plan" });
    data.plan.forEach((s) => plan.append(el("li", {}, el("code", { text: s }))));
    $("plan-box").append(el("h3", { text: "Plan" }), plan);
  }
  curve();
  window.addEventListener("resize", resize);
  resize(); fit();
  if (nodes.length) select(goal || nodes[0], false);
  // For tests and scripts: select a node by id, and where a node is drawn on the page.
  window.explorer = {
    select: (id) => select(byId.get(id), true),
    position: (id) => { const n = byId.get(id); const b = canvas.getBoundingClientRect(); const [x, y] = toScreen(n.x, n.y); return [b.left + x, b.top + y]; },
    count: nodes.length,
    openedMs: performance.now(),  // since the navigation began: parse, layout, first drawing
    ready: true,
  };
})();
