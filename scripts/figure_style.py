"""The look every mhbench figure shares (plot_study.py, plot_flux_map.py): sizes of a two-column
paper, 8-9 pt serif text, a colour-blind-safe palette, PDF with TrueType fonts and a PNG for the
HTML page. Imported from the scripts' own folder (installed beside them, share/mhbench/scripts/)."""

COLUMN = 3.5  # in: one column of a two-column paper (IEEE, Elsevier)
TWO_COLUMNS = 7.16
# Sharp on the HTML page at the figure's own size (a one-column figure is 490 px wide, checked by
# eye); more pixels cost rasterising and compressing time (120 dpi saved 8% of a four-panel figure
# against 160) for detail a reader zooms into the PDF for.
PNG_DPI = 140
# Okabe & Ito (2008), safe for every common colour-vision deficiency; yellow last (weak on white).
PALETTE = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"]
NEUTRAL = "#555555"
FORMATS = ("pdf", "png")

RC = {
    "pdf.fonttype": 42,  # TrueType, embedded: the text stays text, journals accept it
    # STIX (Times-like, as most journals' text) with DejaVu Serif for what it lacks (the
    # superscript digits of the log axes' "10⁻⁵"): matplotlib falls back glyph by glyph.
    "font.family": ["STIXGeneral", "DejaVu Serif"],
    "mathtext.fontset": "stix",
    "font.size": 8, "axes.titlesize": 8.5, "axes.labelsize": 8, "xtick.labelsize": 7,
    "ytick.labelsize": 7, "legend.fontsize": 7, "figure.titlesize": 9,
    "axes.linewidth": 0.6, "lines.linewidth": 1.1, "lines.markersize": 3.5,
    "xtick.major.width": 0.6, "ytick.major.width": 0.6, "grid.linewidth": 0.4,
    "grid.alpha": 0.45, "axes.grid": True, "legend.frameon": False,
    "legend.handlelength": 2.6, "savefig.dpi": PNG_DPI,
    # Titles at a fixed height above the axes: matplotlib's automatic one measures every tick label
    # of the axes again for each title and format (a tenth of a figure's time), to avoid labels on
    # top, which no figure here has.
    "axes.titley": 1.0,
    "axes.prop_cycle": None,  # set below from PALETTE
}


def use_style(matplotlib):
    """Agg (no window) and the shared rcParams, once per process: every figure then inherits them."""
    from cycler import cycler

    matplotlib.use("Agg")
    rc = dict(RC)
    rc["axes.prop_cycle"] = cycler(color=PALETTE)
    matplotlib.rcParams.update(rc)


def pdf_metadata(name):
    """No date in the PDF, so that a figure drawn again is the same file."""
    return {"Title": name, "CreationDate": None}


def save_figure(fig, out_dir, name, before_each=None):
    """Writes NAME.pdf and NAME.png whole or not at all: each under a temporary name (.NAME.EXT.tmp-PID,
    which plot_study.py's next run removes if its process is gone), then renamed. Fixed margins, no
    bbox_inches="tight": that would draw each format twice. `before_each()` runs before each format
    (a stop check)."""
    import os

    for ext in FORMATS:
        if before_each is not None:
            before_each()
        final = os.path.join(out_dir, name + "." + ext)
        temporary = os.path.join(out_dir, ".%s.%s.tmp-%d" % (name, ext, os.getpid()))
        try:
            fig.savefig(temporary, format=ext, metadata=pdf_metadata(name) if ext == "pdf" else {"Title": name})
            os.replace(temporary, final)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
