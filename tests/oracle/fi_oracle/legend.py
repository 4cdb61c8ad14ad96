"""The plugin's valence legend, as its README and vcg_ext/irregular/legend.h state it:
equivalent valence (interior valence, boundary valence + 2) -> RGB."""
import numpy as np

from .topology import as_mesh, equivalent_valences

__all__ = ["LEGEND", "legend_rgb", "expected_rgb"]

LEGEND = {3: (150, 40, 190), 4: (0, 175, 200), 5: (40, 80, 230), 6: (200, 200, 200),
          7: (245, 140, 20), 8: (215, 30, 30), 9: (110, 0, 20)}


def legend_rgb(equivalent_valence):
    """Colour of one equivalent valence (3 or less: purple, 9 or more: dark red)."""
    return LEGEND[min(max(int(equivalent_valence), 3), 9)]


def expected_rgb(mesh):
    """(n, 3) uint8: the legend colour every vertex should have after a colouring filter."""
    eq = equivalent_valences(as_mesh(mesh))
    table = np.array([legend_rgb(k) for k in range(0, 10)], dtype=np.uint8)
    return table[np.clip(eq, 0, 9)]
