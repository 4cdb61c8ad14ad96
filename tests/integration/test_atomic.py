"""Integration: 'Irregular Vertices: Atomic Operation' through meshlabserver on the bunny."""
import os

import numpy as np

from mlpy import (EXAMPLES, Enum, Filter, check_invariants, read_off, run, select_vertices,
                      selected_mask, valences)

OPS = ["5-7 pair move", "v5/v7 move with 5-7 pair generation",
       "v5/v7 move with 5-7 pair removal (triple cancellation)", "5-5-7-7 generation by flip",
       "5-5-7-7 generation by split", "5-5-7-7 removal", "Edge flip", "Edge collapse", "Vertex split"]


def atomic(op, direction=0, relax=True, colorize=True):
    return Filter("Irregular Vertices: Atomic Operation", operation=Enum(op, OPS), direction=direction, relax=relax,
                  colorize=colorize)


def hist(val):
    return np.bincount(val, minlength=16)


def test_example_round_trip_keeps_valences(corpus):
    src = read_off(corpus("bunny00.off"))
    r = run(corpus("bunny00.off"), filters=os.path.join(EXAMPLES, "atomic.mlx"))
    assert r.ok, r.log
    assert np.array_equal(hist(valences(r.mesh)), hist(valences(src)))
    assert "5-5-7-7 quadruple removed" in r.log
    check_invariants(r.mesh)


def test_quadruple_generation_by_split_adds_a_vertex(corpus):
    src = read_off(corpus("bunny00.off"))
    r = run(corpus("bunny00.off"), filters=[select_vertices([98]), atomic(4)])
    assert r.ok, r.log
    m = r.mesh
    assert len(m.vertices) == len(src.vertices) + 1
    assert len(m.faces) == len(src.faces) + 2
    h0, h1 = hist(valences(src)), hist(valences(m))
    assert h1[5] == h0[5] + 2 and h1[7] == h0[7] + 2 and h1[6] == h0[6] - 3
    sel = selected_mask(m)
    assert sorted(valences(m)[sel]) == [5, 5, 7, 7]
    check_invariants(m)


def first_vertex(val, d):
    return int(np.nonzero(val == d)[0][0])


def test_single_vertex_cannot_move_alone(corpus):
    val = valences(read_off(corpus("bunny00.off")))
    r = run(corpus("bunny00.off"), filters=[select_vertices([first_vertex(val, 5)]), atomic(0)])
    assert r.returncode == 255
    assert "Theorem 5.1" in r.log
    assert not os.path.exists(r.output_path)


def test_five_seven_pair_cannot_cancel(corpus):
    m = read_off(corpus("bunny00.off"))
    val = valences(m)
    # an adjacent 5-7 pair
    f = m.faces
    for a, b in np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]):
        if val[a] == 5 and val[b] == 7:
            break
    r = run(corpus("bunny00.off"), filters=[select_vertices([int(a), int(b)]), atomic(2)])
    assert r.returncode == 255
    assert "Theorem 5.5" in r.log


def test_wrong_selection_is_refused(corpus):
    r = run(corpus("bunny00.off"), filters=[select_vertices([98, 99, 100]), atomic(3)])
    assert r.returncode == 255
    assert "exactly 1 selected" in r.log or "exactly one" in r.log or "needs exactly" in r.log
