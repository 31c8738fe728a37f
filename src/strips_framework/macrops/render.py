"""Pictures of a triangle table, drawn the way the 1972 paper draws them: row r holds op_r
at its right end and, to its left, what op_r needs, by the column that supplied it; the
last row holds the goal's clauses. Marked (supporting) clauses carry a ``*``; kernel i is
the rectangle of rows i .. n+1 and columns 0 .. i-1 (outlined in the SVG, listed in the
text).
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


_CELL_W, _LINE_H, _PAD = 190, 16, 6
_KERNEL_COLOURS = ("#c0392b", "#2471a3", "#229954", "#b7950b", "#7d3c98", "#ca6f1e")


def svg_table(table: TriangleTable, title: str = "", kernel: int | None = None) -> str:
    """The table as SVG: a grid of cells, operator cells shaded, marked clauses in bold,
    and the kernels outlined (only ``kernel`` when one is given)."""
    grid = _grid(table)
    n = table.size
    heights = [max(1, *(len(c) for c in cells)) * _LINE_H + 2 * _PAD for cells in grid]
    top = 30 if title else 8
    tops = [top]
    for h in heights:
        tops.append(tops[-1] + h)
    width, height = (n + 1) * _CELL_W + 20, tops[-1] + 10
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
             f'font-family="monospace" font-size="12">']
    if title:
        parts.append(f'<text x="10" y="20" font-size="14">{escape(title)}</text>')
    for r, cells in enumerate(grid):
        for c, lines in enumerate(cells):
            x, y = 10 + c * _CELL_W, tops[r]
            fill = "#eeeeee" if (r < n and c == r + 1) else "white"
            parts.append(f'<rect x="{x}" y="{y}" width="{_CELL_W}" height="{heights[r]}" '
                         f'fill="{fill}" stroke="#555"/>')
            for k, line in enumerate(lines):
                weight = "bold" if line.startswith("*") else "normal"
                parts.append(f'<text x="{x + _PAD}" y="{y + _PAD + (k + 1) * _LINE_H - 4}" '
                             f'font-weight="{weight}">{escape(line)}</text>')
    chosen = [kernel] if kernel is not None else list(range(1, n + 2))
    for i in chosen:
        inset = 2 + 2 * ((i - 1) % 4)
        x, y = 10 + inset, tops[i - 1] + inset
        w, h = i * _CELL_W - 2 * inset, tops[-1] - tops[i - 1] - 2 * inset
        colour = _KERNEL_COLOURS[(i - 1) % len(_KERNEL_COLOURS)]
        parts.append(f'<rect x="{x}" y="{y}" width="{w}" height="{h}" fill="none" '
                     f'stroke="{colour}" stroke-width="2" stroke-dasharray="6,3">'
                     f'<title>kernel {i}</title></rect>')
    parts.append("</svg>")
    return "\n".join(parts) + "\n"


def html_table(table: TriangleTable, title: str = "", kernel: int | None = None) -> str:
    """A page with the SVG picture and, below it, the kernels and constraints as text."""
    text = text_table(table).split("\n\n", 1)[1]
    return (
        "<!DOCTYPE html>\n<html><head><meta charset='utf-8'>"
        f"<title>{escape(title or 'triangle table')}</title></head><body>\n"
        f"<h1>{escape(title or 'triangle table')}</h1>\n"
        f"{svg_table(table, '', kernel)}"
        f"<pre>{escape(text)}</pre>\n</body></html>\n"
    )
