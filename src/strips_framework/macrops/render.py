"""Pictures of a triangle table, drawn the way the 1972 paper draws them: row r holds op_r
at its right end and, to its left, what op_r needs, by the column that supplied it; the
last row holds the goal's clauses. Marked (supporting) clauses carry a ``*``; kernel i is
the rectangle of rows i .. n+1 and columns 0 .. i-1 (outlined in the SVG, one at a
time in the HTML page, listed in the text).
"""

from __future__ import annotations

from html import escape

from strips_framework.logic.terms import atom_to_str
from strips_framework.macrops.table import TriangleTable, cells_by_row


def _cell_lines(table: TriangleTable, row: int, col: int) -> list[str]:
    marked, unmarked = cells_by_row(table)[row - 1][col]
    return [f"*{atom_to_str(a)}" for a in marked] + [f" {atom_to_str(a)}" for a in unmarked]


def _grid(table: TriangleTable) -> list[list[list[str]]]:
    """``[row][col]`` text lines, with op_r in column r of row r."""
    n = table.size
    grid = []
    for row in range(1, n + 2):
        cells = [_cell_lines(table, row, col) for col in range(row)]
        if row <= n:
            cells.append([f"{row}: {table.steps[row - 1]}"])
        grid.append(cells)
    return grid


def text_table(table: TriangleTable, title: str = "") -> str:
    """The table as text, one box per cell, then the kernels and the constraints."""
    grid = _grid(table)
    n = table.size
    widths = [max([len(line) for cells in grid for line in (cells[c] if c < len(cells) else [])]
                  + [len(f"col {c}")]) for c in range(n + 1)]
    out = [title] if title else []
    out.append("     " + " | ".join(f"col {c}".ljust(widths[c]) for c in range(n + 1)))
    for r, cells in enumerate(grid, start=1):
        height = max(1, *(len(c) for c in cells))
        out.append("-" * (5 + sum(widths) + 3 * n))
        for k in range(height):
            label = f"r{r}".ljust(4) if k == 0 else "    "
            parts = [(cells[c][k] if k < len(cells[c]) else "").ljust(widths[c])
                     for c in range(len(cells))]
            out.append((label + " " + " | ".join(parts)).rstrip())
    out.append("")
    out.append("* marks a supporting clause (used by the row's operator, or the goal).")
    for i in range(1, n + 2):
        what = "the goal" if i == n + 1 else f"steps {i}..{n} apply"
        atoms = ", ".join(map(atom_to_str, table.kernel(i))) or "true"
        out.append(f"kernel {i} ({what}): {atoms}")
    for d in table.distinct:
        out.append(f"distinct: {atom_to_str(('=', d.left, d.right)).replace(' = ', ' != ')}"
                   f"  (else step {d.step} deletes what row {d.row} needs)")
    return "\n".join(out) + "\n"


#: Pixels: a monospace character at 12 px, a text line, a cell's padding; the widest
#: line a cell gets before it wraps (the whole text is on the cell's hover title).
_CHAR_W, _LINE_H, _PAD = 7.3, 16, 6
_MAX_CHARS = 34
#: Kernel outlines: distinct colours (ten, then dashes tell the next ten apart) and the
#: space between the nested outlines' left and bottom edges, which all kernels share.
_KERNEL_COLOURS = ("#c0392b", "#2471a3", "#229954", "#b7950b", "#7d3c98", "#ca6f1e",
                   "#17a589", "#566573", "#d4ac0d", "#a93226")
_KERNEL_STEP = 4
#: Room at each cell's right for the label of the kernel whose corner is there.
_LABEL_W = 24


def _wrap(line: str, limit: int = _MAX_CHARS) -> list[str]:
    """``line`` in pieces of at most ``limit`` characters, broken after ", " or "(" where
    possible (a continuation is indented two spaces); nothing is dropped."""
    pieces, rest = [], line
    while len(rest) > limit:
        cut = max(rest.rfind(", ", 0, limit) + 2, rest.rfind("(", 0, limit) + 1)
        if cut < limit // 3:
            cut = limit
        pieces.append(rest[:cut].rstrip())
        rest = "  " + rest[cut:].lstrip()
    return [*pieces, rest]


def _layout(grid: list[list[list[str]]], n: int) -> tuple[list[list[list[str]]], list[float]]:
    """The wrapped lines of every cell and each column's width in pixels."""
    wrapped = [[[piece for line in cell for piece in _wrap(line)] for cell in cells] for cells in grid]
    widths = []
    for col in range(n + 1):
        longest = max((len(line) for cells in wrapped if col < len(cells) for line in cells[col]),
                      default=0)
        widths.append(max(longest, 8) * _CHAR_W + 2 * _PAD + _LABEL_W)
    return wrapped, widths


def svg_table(table: TriangleTable, title: str = "", kernel: int | None = None) -> str:
    """The table as SVG: a grid of cells, operator cells shaded, marked clauses in bold,
    every clause whole (long ones wrapped; each cell's full text on hover) and the
    kernels outlined (only ``kernel`` when one is given). Kernel i is the rectangle of
    rows i .. n+1 and columns 0 .. i-1, so all kernels share the bottom-left corner:
    there each outline runs a few pixels outside the previous one (in a gutter beside
    and below the table, clear of the text), in its own colour,
    and is labelled Ki at its top-right corner, its own."""
    n = table.size
    grid, widths = _layout(_grid(table), n)
    heights = [max(1, *(len(c) for c in cells)) * _LINE_H + 2 * _PAD for cells in grid]
    gutter = 6 + _KERNEL_STEP * (n + 1)  # the outlines' left and bottom edges go here
    top = 30 if title else 8
    tops = [top]
    for h in heights:
        tops.append(tops[-1] + h)
    lefts = [10.0 + gutter]
    for w in widths:
        lefts.append(lefts[-1] + w)
    width, height = lefts[-1] + 10, tops[-1] + gutter + 4
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height}" '
             f'font-family="monospace" font-size="12" class="triangle-table">']
    if title:
        parts.append(f'<text x="10" y="20" font-size="14">{escape(title)}</text>')
    originals = _grid(table)
    for r, cells in enumerate(grid):
        for c, lines in enumerate(cells):
            x, y = lefts[c], tops[r]
            operator = r < n and c == r + 1
            fill = "#eeeeee" if operator else "white"
            full = "\n".join(line.strip() for line in originals[r][c]) or "(empty)"
            parts.append(f'<g class="cell" data-row="{r + 1}" data-col="{c}"><title>{escape(full)}</title>'
                         f'<rect x="{x:.1f}" y="{y}" width="{widths[c]:.1f}" height="{heights[r]}" '
                         f'fill="{fill}" stroke="#555"/>')
            bold = False
            for k, line in enumerate(lines):
                if not line.startswith("  "):
                    bold = line.startswith("*")
                weight = "bold" if bold else "normal"
                parts.append(f'<text x="{x + _PAD:.1f}" y="{y + _PAD + (k + 1) * _LINE_H - 4}" '
                             f'font-weight="{weight}" xml:space="preserve">{escape(line)}</text>')
            parts.append("</g>")
    chosen = [kernel] if kernel is not None else list(range(1, n + 2))
    for i in chosen:
        shift = 3 + _KERNEL_STEP * (i - 1)
        left, bottom = lefts[0] - shift, tops[-1] + shift
        top_edge, right = tops[i - 1] + 2, lefts[i] - 2
        colour = _KERNEL_COLOURS[(i - 1) % len(_KERNEL_COLOURS)]
        dash = ' stroke-dasharray="7,3"' if (i - 1) // len(_KERNEL_COLOURS) % 2 else ""
        parts.append(f'<g class="kernel" data-kernel="{i}"><title>kernel {i}</title>'
                     f'<rect x="{left:.1f}" y="{top_edge}" width="{right - left:.1f}" '
                     f'height="{bottom - top_edge}" fill="none" stroke="{colour}" '
                     f'stroke-width="2"{dash}/>'
                     f'<text x="{right - 3:.1f}" y="{top_edge + 13}" text-anchor="end" '
                     f'font-weight="bold" fill="{colour}">K{i}</text></g>')
    parts.append("</svg>")
    return "\n".join(parts) + "\n"


_HTML_STYLE = """
body { font: 14px system-ui, sans-serif; margin: 12px; }
#kernels button { margin: 0 4px 4px 0; font: 12px monospace; }
#kernels button.active { outline: 2px solid #1f618d; }
svg.one .kernel { display: none; } svg.one .kernel.active { display: inline; }
svg .cell.inside rect { fill: #fdf2e9; }
svg .cell:hover rect { stroke-width: 2; }
#kernel-text, pre { font: 12px monospace; white-space: pre-wrap; }
"""

_HTML_SCRIPT = """
(function () {
  const svg = document.querySelector("svg.triangle-table");
  const buttons = document.querySelectorAll("#kernels button");
  const texts = JSON.parse(document.getElementById("kernel-data").textContent);
  function show(k) {
    svg.classList.toggle("one", k !== "all");
    buttons.forEach((b) => b.classList.toggle("active", b.dataset.kernel === String(k)));
    svg.querySelectorAll(".kernel").forEach((g) => g.classList.toggle("active", g.dataset.kernel === String(k)));
    svg.querySelectorAll(".cell").forEach((c) => {
      const inside = k !== "all" && +c.dataset.row >= k && +c.dataset.col < k;
      c.classList.toggle("inside", inside);
    });
    document.getElementById("kernel-text").textContent = k === "all" ? "" : texts[k - 1];
  }
  buttons.forEach((b) => {
    const k = b.dataset.kernel === "all" ? "all" : +b.dataset.kernel;
    b.addEventListener("click", () => show(k));
    b.addEventListener("mouseenter", () => show(k));
  });
  svg.querySelectorAll(".cell").forEach((c) => {
    const row = +c.dataset.row, col = +c.dataset.col;
    if (col === row) c.addEventListener("click", () => show(row));  // op_i: its kernel
  });
  window.showKernel = show;
  show(1);
})();
"""


def html_table(table: TriangleTable, title: str = "", kernel: int | None = None) -> str:
    """A page with the SVG picture, one kernel shown at a time (hover or click its
    button, or click an operator's cell: op_i applies in kernel i) with its cells shaded
    and its clauses listed, and below, the kernels and constraints as text."""
    import json

    n = table.size
    text = text_table(table).split("\n\n", 1)[1]
    kernels = [", ".join(map(atom_to_str, table.kernel(i))) or "true" for i in range(1, n + 2)]
    buttons = "".join(f'<button data-kernel="{i}">K{i}</button>' for i in range(1, n + 2))
    heading = escape(title or "triangle table")
    data = json.dumps([f"kernel {i}: {k}" for i, k in enumerate(kernels, start=1)])
    data = data.replace("</", "<\\/")  # would end the script element early
    return (
        "<!DOCTYPE html>\n<html><head><meta charset='utf-8'>"
        f"<title>{heading}</title><style>{_HTML_STYLE}</style></head><body>\n"
        f"<h1>{heading}</h1>\n"
        f'<div id="kernels">kernel: {buttons}<button data-kernel="all">all</button></div>\n'
        f"{svg_table(table, '', kernel)}"
        f'<p id="kernel-text"></p>\n'
        f'<script type="application/json" id="kernel-data">{data}</script>\n'
        f"<pre>{escape(text)}</pre>\n<script>{_HTML_SCRIPT}</script>\n</body></html>\n"
    )
