"""Integration: the composite filters (sec. 6.3, 7) through meshlabserver on corpus meshes:
every example script, long moves, refusals."""
import os

import numpy as np
import pytest

from mlpy import (EXAMPLES, Enum, Filter, Point3f, check_invariants, irregular_mask, read_off, run,
                      select_vertices, selected_mask, valences)

LEAD = ["Lower valence", "Higher valence", "Lower index", "Higher index"]


def hist(m):
    v = valences(m)
    return np.bincount(v[irregular_mask(m)], minlength=16)


def move_pair(direction=0, steps=5, toward=False, point=(0.0, 0.0, 0.0), relax=True, colorize=True):
    return Filter("Irregular Vertices: Move Pair", lead=Enum(0, LEAD), direction=direction, steps=steps,
                  towardPoint=toward, point=Point3f(*point), relax=relax, colorize=colorize)


def preserved_irregular(src, out):
    """Input irregular vertices found at the same position with the same valence in the output."""
    sv, ov = valences(src), valences(out)
    idx = np.nonzero(irregular_mask(src))[0]
    kept = 0
    for i in idx:  # the PLY stores float32: match positions within a tolerance
        near = np.nonzero(np.linalg.norm(out.vertices - src.vertices[i], axis=1) < 1e-5)[0]
        kept += any(ov[j] == sv[i] for j in near)
    return kept, len(idx)


def test_reduce_example(corpus):
    src = read_off(corpus("bunny00.off"))
    r = run(corpus("bunny00.off"), filters=os.path.join(EXAMPLES, "reduce.mlx"))
    assert r.ok, r.log
    before, after = hist(src), hist(r.mesh)
    # most vertices of valence other than 5 and 7 are gone
    other_before = before.sum() - before[5] - before[7]
    other_after = after.sum() - after[5] - after[7]
    assert other_after < 0.1 * other_before, (other_before, other_after)
    assert "Reduced" in r.log
    check_invariants(r.mesh)


def test_aggregate_example_restores_histogram(corpus):
    src = read_off(corpus("bunny00.off"))
    r = run(corpus("bunny00.off"), filters=os.path.join(EXAMPLES, "aggregate.mlx"))
    assert r.ok, r.log
    assert np.array_equal(hist(r.mesh), hist(src))
    sel = selected_mask(r.mesh)
    assert list(valences(r.mesh)[sel]) == [8]
    check_invariants(r.mesh)


def test_move_pair_example(corpus):
    src = read_off(corpus("knot1.off"))
    r = run(corpus("knot1.off"), filters=os.path.join(EXAMPLES, "move_pair.mlx"))
    assert r.ok, r.log
    m = r.mesh
    assert np.array_equal(hist(m), hist(src))
    sel = np.nonzero(selected_mask(m))[0]
    assert sorted(valences(m)[sel]) == [5, 7]
    # the pair moved: its old place is regular now
    assert valences(m)[47] == 6 or np.linalg.norm(m.vertices[47] - src.vertices[47]) > 0
    check_invariants(m)


@pytest.mark.parametrize("steps", [30])
def test_long_move_touches_nothing_far_away(corpus, steps):
    src = read_off(corpus("knot1.off"))
    # without relaxation nothing but the path's own vertices can move
    r = run(corpus("knot1.off"), filters=[select_vertices([47, 3186]), move_pair(0, steps, relax=False)])
    assert r.ok, r.log
    m = r.mesh
    assert "%d atomic steps" % steps in r.log
    assert np.array_equal(hist(m), hist(src))
    sel = np.nonzero(selected_mask(m))[0]
    assert sorted(valences(m)[sel]) == [5, 7]
    # the pair is far from where it started
    start = (src.vertices[47] + src.vertices[3186]) / 2
    end = m.vertices[sel].mean(0)
    edge = np.linalg.norm(src.vertices[src.faces[:, 0]] - src.vertices[src.faces[:, 1]], axis=1).mean()
    assert np.linalg.norm(end - start) > 3 * edge  # the knot's tube is thin: Euclidean underestimates
    kept, total = preserved_irregular(src, m)
    # every irregular vertex but the moved pair keeps its place and valence
    assert kept == total - 2, (kept, total)
    check_invariants(m)


def test_move_toward_point(corpus):
    src = read_off(corpus("knot1.off"))
    start = (src.vertices[47] + src.vertices[3186]) / 2
    target = src.vertices[1500]
    r = run(corpus("knot1.off"), filters=[select_vertices([47, 3186]), move_pair(toward=True, point=tuple(map(float, target)))])
    if not r.ok:
        assert "Irregular Vertices: refused" in r.log
        return
    sel = np.nonzero(selected_mask(r.mesh))[0]
    end = r.mesh.vertices[sel].mean(0)
    assert np.linalg.norm(end - target) < np.linalg.norm(start - target)
    check_invariants(r.mesh)


@pytest.mark.parametrize("script", ["cancel_triple.mlx", "cancel_quadruple.mlx"])
def test_generate_then_cancel_examples(corpus, script):
    src = read_off(corpus("knot1.off"))
    r = run(corpus("knot1.off"), filters=os.path.join(EXAMPLES, script))
    assert r.ok, r.log
    assert np.array_equal(hist(r.mesh), hist(src))
    check_invariants(r.mesh)


def test_generate_example(corpus):
    src = read_off(corpus("knot1.off"))
    r = run(corpus("knot1.off"), filters=os.path.join(EXAMPLES, "generate.mlx"))
    assert r.ok, r.log
    h0, h1 = hist(src), hist(r.mesh)
    assert h1[5] == h0[5] + 2 and h1[7] == h0[7] + 2
    sel = selected_mask(r.mesh)
    assert sorted(valences(r.mesh)[sel]) == [5, 5, 7, 7]
    check_invariants(r.mesh)


def test_refusals(corpus):
    src = read_off(corpus("knot1.off"))
    val = valences(src)
    # a 5-7 pair cannot cancel (Theorem 5.5)
    r = run(corpus("knot1.off"), filters=[select_vertices([47, 3186]), Filter("Irregular Vertices: Cancel Triple", relax=True, colorize=True)])
    assert r.returncode == 255 and "Theorem 5.5" in r.log and not os.path.exists(r.output_path)
    # one irregular vertex cannot move alone (Theorem 5.1)
    r = run(corpus("knot1.off"), filters=[select_vertices([47]), move_pair()])
    assert r.returncode == 255 and "Theorem 5.1" in r.log
    # aggregation of regular vertices
    regular = [int(i) for i in np.nonzero(val == 6)[0][:2]]
    r = run(corpus("knot1.off"), filters=[select_vertices(regular), Filter("Irregular Vertices: Aggregate", relax=True, colorize=True)])
    assert r.returncode == 255 and "aggregation merges only" in r.log
    # wrong count
    r = run(corpus("knot1.off"), filters=[select_vertices([47, 3186, 5, 6, 7]), Filter("Irregular Vertices: Cancel Quadruple", relax=True, colorize=True)])
    assert r.returncode == 255 and "needs exactly 4" in r.log
