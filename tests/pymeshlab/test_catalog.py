"""The plugin as pymeshlab sees it: its twelve filters, every parameter with its Python name, type
and default (as README and filter_catalog.cpp state them), a table saying which test exercises
each parameter (so a parameter added without a test fails here), and the two parameters every
editing filter shares, 'relax' and 'colorize', checked on each of them."""
import inspect
import re

import numpy as np
import pymeshlab
import pytest

import fi_oracle as fo
from fi_pm import (AGGREGATE, ANALYZE, ATOMIC, AUTOMATIC, BOUNDARY, CANCEL_QUADRUPLE, CANCEL_TRIPLE, FILTERS, GENERATE,
                   MOVE_PAIR, PATTERN, REDUCE, RELAX, apply, index_by_position, painted, quality, rgb, select, state, tri)

# pymeshlab name -> [(python parameter name, type as pymeshlab prints it, default as printed)]
EXPECTED = {
    ANALYZE: [("select", "str", "'All irregular'"), ("valence", "int", "5"), ("colorize", "bool", "True")],
    ATOMIC: [("operation", "str", "'5-7 pair move'"), ("direction", "int", "0"), ("via", "str", "'Any'"),
             ("pairside", "str", "'Any'"), ("towardpoint", "bool", "False"),
             ("point", "numpy.ndarray[numpy.float64[3]]", "[0, 0, 0]"), ("relax", "bool", "True"),
             ("colorize", "bool", "True")],
    RELAX: [("mode", "str", "'Local'"), ("iterations", "int", "10"), ("region", "str", "'All'"),
            ("reproject", "bool", "True"), ("featureangle", "float", "60")],
    REDUCE: [("scope", "str", "'All irregular vertices'"), ("relax", "bool", "True"), ("colorize", "bool", "True")],
    AGGREGATE: [("relax", "bool", "True"), ("colorize", "bool", "True")],
    MOVE_PAIR: [("lead", "str", "'Lower valence'"), ("direction", "int", "0"), ("steps", "int", "1"),
                ("towardpoint", "bool", "False"), ("point", "numpy.ndarray[numpy.float64[3]]", "[0, 0, 0]"),
                ("relax", "bool", "True"), ("colorize", "bool", "True")],
    CANCEL_TRIPLE: [("relax", "bool", "True"), ("colorize", "bool", "True")],
    CANCEL_QUADRUPLE: [("relax", "bool", "True"), ("colorize", "bool", "True")],
    GENERATE: [("kind", "str", "'Triple from a v5 or v7'"), ("direction", "int", "0"), ("spacing", "int", "2"), ("shape", "str", "'Move apart'"),
               ("side1direction", "int", "4"), ("side1", "int", "3"), ("side2direction", "int", "1"), ("side2", "int", "0"),
               ("relax", "bool", "True"), ("colorize", "bool", "True")],
    AUTOMATIC: [("remeshedgelength", "PercentageValue", "0%"), ("targetcount", "int", "0"),
                ("hausdorffbudget", "float", "0.5"), ("minangle", "float", "30"), ("angleallowance", "float", "0.8"),
                ("anglefloor", "float", "20"), ("maxtravel", "int", "12"),
                ("protect", "str", "'Nothing'"), ("relaxation", "str", "'Local'"), ("timelimit", "float", "60"),
                ("aggregate", "bool", "False"), ("colorize", "bool", "True")],
    BOUNDARY: [("operation", "str", "'Absorb into the boundary'"), ("side", "str", "'First boundary neighbour'"),
               ("pairdirection", "str", "'Towards its valence-3 vertex'"), ("steps", "int", "1"),
               ("relax", "bool", "True"), ("colorize", "bool", "True")],
    PATTERN: [("pattern", "str", "'Stripes'"), ("direction", "int", "0"), ("period", "int", "2"),
              ("starradius", "int", "3"), ("ringwidth", "int", "1"), ("panels", "bool", "False"),
              ("panelinset", "float", "0.15"), ("panelextrusion", "float", "0.25")],
}

# (filter, parameter) -> the tests that run it with other values than the default and check
# the effect ("module::function"); relax and colorize of the editing filters: this file.
SHARED = "test_catalog::test_relax_and_colorize_of_every_editing_filter"
EXERCISED = {
    (ANALYZE, "select"): ["test_analyze::test_select_only_valence", "test_analyze::test_select_none_keeps_the_users_selection"],
    (ANALYZE, "valence"): ["test_analyze::test_only_valence_counts_boundary_vertices_as_valence_plus_two"],
    (ANALYZE, "colorize"): ["test_analyze::test_colorize_off_keeps_colours_and_writes_quality"],
    (ATOMIC, "operation"): ["test_atomic::test_quadruple_generation_by_flip_every_direction_and_removal",
                            "test_atomic::test_vertex_split_keeps_the_counter_clockwise_side"],
    (ATOMIC, "direction"): ["test_atomic::test_pair_move_every_direction_lands_where_the_paper_says"],
    (ATOMIC, "via"): ["test_atomic::test_move_with_pair_generation_then_removal"],
    (ATOMIC, "pairside"): ["test_atomic::test_move_with_pair_generation_then_removal"],
    (ATOMIC, "towardpoint"): ["test_atomic::test_move_with_pair_generation_toward_a_point"],
    (ATOMIC, "point"): ["test_atomic::test_move_with_pair_generation_toward_a_point"],
    (GENERATE, "shape"): ["test_composite::test_generate_a_quadruple_of_a_given_shape_then_cancel_it"],
    (GENERATE, "side1direction"): ["test_composite::test_generate_a_quadruple_of_a_given_shape_then_cancel_it"],
    (GENERATE, "side1"): ["test_composite::test_generate_a_quadruple_of_a_given_shape_then_cancel_it"],
    (GENERATE, "side2direction"): ["test_composite::test_generate_a_quadruple_of_a_given_shape_then_cancel_it"],
    (GENERATE, "side2"): ["test_composite::test_generate_a_quadruple_of_a_given_shape_then_cancel_it"],
    (ATOMIC, "relax"): ["test_atomic::test_pair_move_with_relaxation_moves_only_the_two_ring_onto_the_surface", SHARED],
    (ATOMIC, "colorize"): ["test_atomic::test_colorize_off_keeps_the_users_colours_and_quality", SHARED],
    (RELAX, "mode"): ["test_relax::test_reprojection_keeps_vertices_on_the_input_surface"],
    (RELAX, "iterations"): ["test_relax::test_zero_iterations_move_nothing"],
    (RELAX, "region"): ["test_relax::test_region_around_irregular_vertices_is_their_two_ring",
                        "test_relax::test_local_relaxation_of_the_selection_moves_only_the_selection"],
    (RELAX, "reproject"): ["test_relax::test_reprojection_keeps_vertices_on_the_input_surface"],
    (RELAX, "featureangle"): ["test_relax::test_feature_angle_keeps_creases"],
    (REDUCE, "scope"): ["test_composite::test_reduce_selected_then_aggregate_restores"],
    (REDUCE, "relax"): [SHARED],
    (REDUCE, "colorize"): [SHARED],
    (AGGREGATE, "relax"): [SHARED],
    (AGGREGATE, "colorize"): [SHARED],
    (MOVE_PAIR, "lead"): ["test_composite::test_non_adjacent_pair_lead_vertex_moves_to_its_neighbour"],
    (MOVE_PAIR, "direction"): ["test_composite::test_long_move_goes_far_and_touches_nothing_else"],
    (MOVE_PAIR, "steps"): ["test_composite::test_long_move_goes_far_and_touches_nothing_else"],
    (MOVE_PAIR, "towardpoint"): ["test_composite::test_move_toward_point_ends_next_to_it"],
    (MOVE_PAIR, "point"): ["test_composite::test_move_toward_point_ends_next_to_it"],
    (MOVE_PAIR, "relax"): ["test_composite::test_long_move_goes_far_and_touches_nothing_else", SHARED],
    (MOVE_PAIR, "colorize"): ["test_composite::test_users_colours_and_quality_survive_where_no_edit_reaches", SHARED],
    (CANCEL_TRIPLE, "relax"): ["test_composite::test_generate_triple_then_cancel_triple_restores_the_input", SHARED],
    (CANCEL_TRIPLE, "colorize"): [SHARED],
    (CANCEL_QUADRUPLE, "relax"): ["test_composite::test_generate_quadruple_spacing", SHARED],
    (CANCEL_QUADRUPLE, "colorize"): [SHARED],
    (GENERATE, "kind"): ["test_composite::test_generate_triple_then_cancel_triple_restores_the_input"],
    (GENERATE, "direction"): ["test_composite::test_generate_triple_then_cancel_triple_restores_the_input"],
    (GENERATE, "spacing"): ["test_composite::test_generate_quadruple_spacing"],
    (GENERATE, "relax"): [SHARED],
    (GENERATE, "colorize"): [SHARED],
    (AUTOMATIC, "remeshedgelength"): ["test_automatic_reduction::test_remeshed_knot_keeps_the_budget"],
    (AUTOMATIC, "targetcount"): ["test_automatic_reduction::test_genus_three_keeps_its_topology_and_stops_at_the_target"],
    (AUTOMATIC, "hausdorffbudget"): ["test_automatic_reduction::test_zero_budget_gives_the_input_back"],
    (AUTOMATIC, "minangle"): ["test_automatic_reduction::test_deterministic_and_every_parameter_has_its_effect"],
    (AUTOMATIC, "angleallowance"): ["test_automatic_reduction::test_deterministic_and_every_parameter_has_its_effect"],
    (AUTOMATIC, "anglefloor"): ["test_automatic_reduction::test_deterministic_and_every_parameter_has_its_effect"],
    (AUTOMATIC, "maxtravel"): ["test_automatic_reduction::test_deterministic_and_every_parameter_has_its_effect"],
    (AUTOMATIC, "protect"): ["test_automatic_reduction::test_protected_region_is_untouched",
                             "test_automatic_reduction::test_protected_irregular_vertices_are_kept"],
    (AUTOMATIC, "relaxation"): ["test_automatic_reduction::test_deterministic_and_every_parameter_has_its_effect"],
    (AUTOMATIC, "timelimit"): ["test_automatic_reduction::test_time_limit_on_a_larger_mesh"],
    (AUTOMATIC, "aggregate"): ["test_automatic_reduction::test_aggregation_merges_leftover_pairs_where_they_were"],
    (AUTOMATIC, "colorize"): ["test_automatic_reduction::test_users_colours_and_quality_survive_where_no_edit_reaches"],
    (BOUNDARY, "operation"): ["test_boundary::test_boundary_v3_moves_along_the_boundary",
                              "test_boundary::test_generated_pair_is_absorbed_again",
                              "test_boundary::test_boundary_pairs_generated_moved_and_cancelled"],
    (BOUNDARY, "side"): ["test_boundary::test_generated_pair_is_absorbed_again"],
    (BOUNDARY, "pairdirection"): ["test_boundary::test_boundary_pairs_generated_moved_and_cancelled"],
    (BOUNDARY, "steps"): ["test_boundary::test_boundary_pairs_generated_moved_and_cancelled"],
    (BOUNDARY, "relax"): ["test_boundary::test_generated_pair_is_absorbed_again"],
    (BOUNDARY, "colorize"): ["test_boundary::test_generated_pair_is_absorbed_again"],
    (PATTERN, "pattern"): ["test_pattern::test_regular_torus_exact"],
    (PATTERN, "direction"): ["test_pattern::test_seed_from_the_selected_vertex_and_the_three_directions"],
    (PATTERN, "period"): ["test_pattern::test_period_three"],
    (PATTERN, "panelinset"): ["test_pattern::test_stripe_panels_inset_and_extrusion"],
    (PATTERN, "panelextrusion"): ["test_pattern::test_stripe_panels_inset_and_extrusion"],
    (PATTERN, "starradius"): ["test_pattern_panels::test_star_seeds_and_isolation_match_an_independent_count"],
    (PATTERN, "panels"): ["test_pattern_panels::test_star_panels_are_a_new_layer_of_closed_shells"],
    (PATTERN, "ringwidth"): ["test_pattern_panels::test_circle_ring_width"],
}


def parameter_lists(capfd):
    """pymeshlab's own description of every filter's parameters (print_filter_parameter_list)."""
    out = {}
    for name in FILTERS:
        pymeshlab.print_filter_parameter_list(name)
        text = capfd.readouterr().out
        rows = re.findall(r"^\t(\w+) : (.+?) = (.+)$", text, re.M)
        out[name] = [(n, t.strip(), d.strip()) for n, t, d in rows]
    return out


def test_the_plugin_provides_twelve_filters():
    import pymeshlab_irregular
    assert sorted(pymeshlab_irregular.load()) == sorted(FILTERS)
    for name in FILTERS:
        assert callable(getattr(pymeshlab.MeshSet, name))


def test_parameters_names_types_defaults(capfd):
    assert parameter_lists(capfd) == EXPECTED


def test_every_parameter_is_exercised_by_a_named_test(capfd):
    """Each (filter, parameter) has tests that exist and whose code passes that parameter."""
    import importlib
    listed = {(f, p) for f, rows in parameter_lists(capfd).items() for p, _, _ in rows}
    assert set(EXERCISED) == listed, "parameters without a test: %s; tests for unknown parameters: %s" % (
        sorted(listed - set(EXERCISED)), sorted(set(EXERCISED) - listed))
    for (filter_name, param), tests in EXERCISED.items():
        for ref in tests:
            module, function = ref.split("::")
            source = inspect.getsource(getattr(importlib.import_module(module), function))
            assert re.search(r"\b%s\s*=" % param, source), "%s does not pass %s to %s" % (ref, param, filter_name)


# ------------------------------------------------------------------ relax and colorize
def setup(filter_name):
    """A painted mesh with the selection the filter needs, and the filter's parameters."""
    if filter_name in (REDUCE, AGGREGATE):
        ms = painted("bunny00.off")
        select(ms, [43])  # a v8
        if filter_name == AGGREGATE:  # first split it into two v7 (positions kept: no relaxation)
            apply(ms, REDUCE, scope="Selected vertices", relax=False, colorize=False)
        return ms, {"scope": "Selected vertices"} if filter_name == REDUCE else {}
    ms = painted("knot1.off")
    if filter_name == ATOMIC:
        select(ms, [206, 2273])
        return ms, {"operation": "5-7 pair move", "direction": 1}
    if filter_name == MOVE_PAIR:
        select(ms, [206, 2273])
        return ms, {"steps": 3, "direction": 1}
    if filter_name == GENERATE:
        select(ms, [25])
        return ms, {"kind": "Quadruple from a regular vertex", "spacing": 2}
    if filter_name == CANCEL_TRIPLE:
        select(ms, [206])
        apply(ms, GENERATE, kind="Triple from a v5 or v7", direction=1, spacing=2, relax=False, colorize=False)
        return ms, {}
    select(ms, [25])
    apply(ms, GENERATE, kind="Quadruple from a regular vertex", spacing=2, relax=False, colorize=False)
    return ms, {}


@pytest.mark.parametrize("filter_name", [ATOMIC, REDUCE, AGGREGATE, MOVE_PAIR, CANCEL_TRIPLE, CANCEL_QUADRUPLE,
                                         GENERATE])
def test_relax_and_colorize_of_every_editing_filter(filter_name):
    """relax=False, colorize=False: vertices the edit did not reach keep position, colour and
    quality, and every colour is one the user painted. relax=True, colorize=True: more
    vertices move (the 2-rings), all stay on the input surface, the legend and the valences
    are painted."""
    ms, params = setup(filter_name)
    t0, before = tri(ms), state(ms)
    apply(ms, filter_name, relax=False, colorize=False, **params)
    t1 = tri(ms)
    where = index_by_position(t0, t1)
    still = where >= 0
    assert still.mean() > 0.95
    colours = ms.current_mesh().vertex_color_matrix()
    assert np.array_equal(colours[still], before["colours"][where[still]])
    assert np.array_equal(quality(ms)[still], before["quality"][where[still]])
    palette = {tuple(c) for c in before["colours"].tolist()}
    assert all(tuple(c) in palette for c in colours.tolist())
    moved_without = (~still).sum()

    ms, params = setup(filter_name)
    apply(ms, filter_name, relax=True, colorize=True, **params)
    t2 = tri(ms)
    moved_with = (index_by_position(t0, t2) < 0).sum()
    assert moved_with > moved_without
    assert fo.closest_point_distances(t2.vertices, t0).max() <= 1e-6 * fo.diagonal(t0)
    assert np.array_equal(rgb(ms), fo.expected_rgb(t2))
    assert np.array_equal(quality(ms), fo.valences(t2).astype(float))
    fo.check_invariants(t2)
