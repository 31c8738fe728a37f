"""The explorer page: one self-contained HTML file (the data, the script and the style
inline; nothing fetched), so it opens from ``file://``, from a mail attachment, or on a
machine without the planner."""

from __future__ import annotations

import json
from html import escape
from importlib.resources import files
from typing import Any

_LEGEND = {
    "world-model": (
        '<span style="background:#d5f5e3">first goal proved</span>'
        '<span style="background:#fadbd8">solution path</span>'
        '<span style="background:#f9e79f">search match</span>'
        '<span style="border-color:#7d3c98;color:#7d3c98">MACROP applied</span>'
        " dark edges: operator applied; light: subgoal"
    ),
    "forward": (
        '<span style="background:#fadbd8">solution path</span>'
        '<span style="background:#d7ccc8">dead end</span>'
        '<span style="background:#f9e79f">search match</span>'
    ),
}


def _asset(name: str) -> str:
    return files("strips_framework.explore").joinpath(name).read_text(encoding="utf-8")


def explorer_page(document: dict[str, Any]) -> str:
    """The page showing ``document`` (:meth:`SearchRecord.document`)."""
    # "</" would end the script element early; JSON allows "<\/" for it.
    payload = json.dumps(document, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    title = escape(document["title"])
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}: search explorer</title>
<style>{_asset("explorer.css")}</style>
</head><body>
<header>
  <div id="summary"></div>
  <input id="search" type="search" placeholder="search goals, operators, facts..." size="34">
  <span id="match-count"></span>
  <button id="fit" title="the whole tree">fit</button>
  <button id="zoom-in">+</button><button id="zoom-out">&minus;</button>
  <button id="goal" title="the goal node">goal</button>
  <span class="legend">{_LEGEND.get(document.get("kind", ""), "")}</span>
</header>
<main>
  <div id="canvas-box"><canvas id="tree"></canvas></div>
  <aside><div id="detail"></div>
    <div id="side-extra"><ul id="matches"></ul><div id="curve"></div><div id="plan-box"></div></div>
  </aside>
</main>
<script type="application/json" id="data">{payload}</script>
<script>{_asset("explorer.js")}</script>
</body></html>
"""
