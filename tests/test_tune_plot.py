"""``python -m physics tune ... --plot PNG``: a real PNG with the Pareto front drawn (issue 19).

The figure is caught as it is saved, so the test checks both its artists (the front line's data
are the front's seconds and errors) and the file's pixels (the line is dark where the artists
put it, the chosen candidate's ring is red)."""
import json

import matplotlib.figure
import matplotlib.image
import numpy as np

from test_tune import small_scene

from physics import cli


def _dark(img, x, y, r=2) -> bool:
    patch = img[max(0, y - r):y + r + 1, max(0, x - r):x + r + 1, :3]
    return bool(np.any(patch.sum(axis=2) < 1.5))  # white is 3; an antialiased 1 px black line ~0.6


def test_plot_file_is_a_png_with_the_front_drawn(tmp_path, monkeypatch, capsys):
    saved = []
    real = matplotlib.figure.Figure.savefig

    def catch(fig, *a, **kw):
        saved.append(fig)
        return real(fig, *a, **kw)
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", catch)
    scene, png, rows = tmp_path / "s.json", tmp_path / "front.png", tmp_path / "rows.json"
    scene.write_text(json.dumps(small_scene()))
    assert cli.main(["tune", str(scene), "--steps", "16", "--budget", "0.05", "--scheduler", "inline",
                     "--modes", "soft_step", "--plot", str(png), "--json", str(rows)]) == 0
    capsys.readouterr()
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    img = matplotlib.image.imread(png)
    assert img.shape[:2] == (450, 700)  # figsize 7 x 4.5 in at 100 dpi
    (fig,) = saved
    ax = fig.axes[0]
    data = json.loads(rows.read_text())
    front = sorted((r for r in data["rows"] if r["front"] and r["error"]), key=lambda r: r["seconds"])
    line = next(ln for ln in ax.lines if ln.get_label() == "Pareto front")
    assert len(front) >= 2
    assert np.allclose(line.get_xdata(), [r["seconds"] for r in front], rtol=1e-12)
    assert np.allclose(line.get_ydata(), [r["error"] for r in front], rtol=1e-12)
    # the pixels: the midpoint of each front segment (display coordinates, y from the top) is dark
    pts = ax.transData.transform(np.column_stack([line.get_xdata(), line.get_ydata()]))
    h = img.shape[0]
    for (x0, y0), (x1, y1) in zip(pts[:-1], pts[1:]):
        mx, my = int(round((x0 + x1) / 2)), int(round(h - (y0 + y1) / 2))
        assert 0 <= mx < img.shape[1] and 0 <= my < h and _dark(img, mx, my), (mx, my)
    # the chosen candidate is ringed in red where its numbers put it
    chosen = next(r for r in data["rows"] if r["key"] == data["choice"])
    cx, cy = ax.transData.transform((chosen["seconds"], chosen["error"]))
    ring = img[int(h - cy) - 12:int(h - cy) + 13, int(cx) - 12:int(cx) + 13, :3]
    red = (ring[..., 0] > 0.8) & (ring[..., 1] < 0.3) & (ring[..., 2] < 0.3)
    assert red.sum() > 10
