"""Print settings shared by every figure script under tools/.

Figures are drawn at their printed width (SINGLE = 3.5 in, one column; DOUBLE = 7.2 in, the
full page), so the font sizes set here are the sizes on paper: 8 pt for ticks and legends,
9 pt for labels and titles. save() writes a vector PDF beside a 200 dpi PNG of the same name.

    import figure_style as fs     # (sys.path: tools/ or tools/verification/)
    fs.apply()
    fig, ax = plt.subplots(figsize=(fs.SINGLE, 2.6))
    fs.panel_label(ax, "a")
    fs.save(fig, "docs/figures/x.png")     # x.png (200 dpi) and x.pdf
"""
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402

SINGLE = 3.5  # in, one column
DOUBLE = 7.2  # in, two columns / full width
DPI = 200

RC = {
    "font.size": 8,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "legend.fontsize": 8,
    "legend.title_fontsize": 8,
    "figure.titlesize": 9,
    "lines.linewidth": 1.0,
    "lines.markersize": 3.5,
    "axes.linewidth": 0.6,
    "xtick.major.width": 0.6,
    "ytick.major.width": 0.6,
    "xtick.minor.width": 0.4,
    "ytick.minor.width": 0.4,
    "grid.linewidth": 0.4,
    "legend.frameon": False,
    "legend.handlelength": 1.8,
    "savefig.dpi": DPI,
    "savefig.bbox": "tight",
    "savefig.pad_inches": 0.02,
    "pdf.fonttype": 42,  # TrueType in the PDF: text stays text
    "svg.fonttype": "none",
}


def apply():
    """Sets the print rcParams (call before creating figures)."""
    plt.rcParams.update(RC)


def save(fig, path, tight=True, formats=("png", "pdf")):
    """Writes PATH with each of the suffixes in `formats` (PNG at 200 dpi; PDF/SVG vector),
    closes the figure and prints the names written. PATH may carry any suffix or none."""
    path = pathlib.Path(path)
    base = path.with_suffix("") if path.suffix in (".png", ".pdf", ".svg") else path
    base.parent.mkdir(parents=True, exist_ok=True)
    if tight and not fig.get_layout_engine():
        fig.tight_layout()
    written = []
    for ext in formats:
        out = base.parent / f"{base.name}.{ext}"
        fig.savefig(out, dpi=DPI if ext == "png" else None)
        written.append(out)
    plt.close(fig)
    return written


def panel_label(ax, letter, x=-0.02, y=1.02):
    """Bold panel letter "(a)" at the upper left. When the axes have a (centred) title, the
    letter leads it and the title moves to the left, so that the two cannot overlap; call
    after set_title. Otherwise the letter stands just outside the upper-left corner."""
    title = ax.get_title()
    if title:
        ax.set_title("")
        ax.set_title(rf"$\bf{{({letter})}}$  {title}", loc="left")
        return
    ax.text(x, y, f"({letter})", transform=ax.transAxes, fontsize=9, fontweight="bold",
            ha="right", va="bottom")


def letters(axes):
    """Panel letters a, b, c, … on the visible axes, in order."""
    for i, ax in enumerate(a for a in axes if a.get_visible()):
        panel_label(ax, chr(ord("a") + i))


def plain_log_ticks(axis, minor_subs=None):
    """Plain numbers (0.5, 1, 2) on a log axis instead of 10^k, with the minor ticks at
    `minor_subs` of each decade labelled too (all minor ticks when the axis spans less than a
    third of a decade), so that every log axis carries several labelled ticks. `minor_subs` defaults to
    2, 3, 5 over up to two decades and 2, 5 over more. Call after the limits are final."""
    lo, hi = axis.get_view_interval()
    narrow = lo > 0 and hi / lo < 3
    if minor_subs is None:
        minor_subs = (2, 3, 5) if lo > 0 and hi / lo <= 100 else (2, 5)

    def fmt(v, _):
        return f"{v:g}"

    def minor(v, _):
        if v <= 0:
            return ""
        lead = round(v / 10 ** math.floor(math.log10(v)), 6)
        return f"{v:g}" if narrow or lead in minor_subs else ""

    axis.set_major_formatter(ticker.FuncFormatter(fmt))
    axis.set_minor_formatter(ticker.FuncFormatter(minor))


def sig(v, digits=2):
    """A number to `digits` significant figures in plain notation down to 1e-4 ("0.00068"),
    "0" for an exact zero."""
    if v == 0 or not math.isfinite(v):
        return "0" if v == 0 else "–"
    e = math.floor(math.log10(abs(v)))
    if e < -4:
        return f"{v:.{digits - 1}e}".replace("e-0", "e-")
    d = max(digits - 1 - e, 0)
    return f"{round(v, d):.{d}f}"


def percent(v, digits=2, floor=0.01):
    """A percentage with `digits` significant figures but at least one decimal ("0.021",
    "7.1", "11.5"), "<0.01" below `floor` and "0" for an exact zero."""
    if v == 0:
        return "0"
    if abs(v) < floor:
        return f"<{floor:g}"
    e = math.floor(math.log10(abs(v)))
    d = max(digits - 1 - e, 0 if abs(v) >= 10 and digits > 2 else 1)
    return f"{round(v, d):.{d}f}"
